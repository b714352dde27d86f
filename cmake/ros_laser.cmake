# Layer 3, ros: the laser driver nodelet amigobot_tracking/Laser and the node laser_node over
# the sensors library.
amigobot_add_library(amigobot_tracking_ros_laser
  src/ros/laser_scan.cpp
  src/ros/laser_node.cpp
  src/ros/laser_nodelet.cpp
)
target_link_libraries(amigobot_tracking_ros_laser amigobot_tracking_sensors amigobot_tracking_ros_params ${catkin_LIBRARIES})

amigobot_add_tool(laser_node src/ros/programs/laser_node.cpp)
target_link_libraries(laser_node amigobot_tracking_ros_laser)

if(CATKIN_ENABLE_TESTING)
  amigobot_add_unit_test(test_laser_scan test/unit/test_laser_scan.cpp)
  target_link_libraries(test_laser_scan amigobot_tracking_ros_laser)
  # Its rostest (laser.test): cmake/rostests.cmake.
endif()

# `make bench`: driver CPU per scan and emulator -> LaserScan latency, in one process.
amigobot_add_benchmark(bench_laser test/bench/bench_laser.cpp amigobot_tracking_ros_laser)
