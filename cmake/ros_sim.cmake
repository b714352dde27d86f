# Layer 3 (simulation part): nodes that stand in for the lab's sensors and localisation on
# the emulated robot: sim_laser (ray-cast world) and ground_truth_localization (map -> odom);
# trail_publisher (rviz trails of the robot and the target) is used on the real robot too.
add_library(amigobot_tracking_ros_sim
  src/ros/sim_laser.cpp
  src/ros/ground_truth.cpp
  src/ros/trail.cpp
)
target_link_libraries(amigobot_tracking_ros_sim amigobot_tracking_ros amigobot_tracking_ros_params amigobot_tracking_aria ${catkin_LIBRARIES})
target_compile_options(amigobot_tracking_ros_sim PRIVATE ${AMIGOBOT_WARNINGS})
install(TARGETS amigobot_tracking_ros_sim LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

amigobot_add_tool(sim_laser src/ros/nodes/sim_laser_node.cpp)
target_link_libraries(sim_laser amigobot_tracking_ros_sim)
amigobot_add_tool(trail_publisher src/ros/nodes/trail_publisher_node.cpp)
target_link_libraries(trail_publisher amigobot_tracking_ros_sim)
amigobot_add_tool(ground_truth_localization src/ros/nodes/ground_truth_localization_node.cpp)
target_link_libraries(ground_truth_localization amigobot_tracking_ros_sim)

if(CATKIN_ENABLE_TESTING)
  amigobot_add_unit_test(test_trail test/unit/test_trail.cpp)
  target_link_libraries(test_trail amigobot_tracking_ros_sim)
  amigobot_add_unit_test(test_sim_laser test/unit/test_sim_laser.cpp)
  target_link_libraries(test_sim_laser amigobot_tracking_ros_sim)
  # The status client against the real emulator executable (free ports, killed on exit).
  amigobot_add_unit_test(test_ground_truth test/unit/test_ground_truth.cpp)
  target_link_libraries(test_ground_truth amigobot_tracking_ros_sim)
  target_include_directories(test_ground_truth PRIVATE test/aria)
  target_compile_definitions(test_ground_truth PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
  add_dependencies(test_ground_truth amigobot_emulator)
endif()

# run_report: a recorded run (rosbag) scored like the offline simulator (make demo).
find_package(rosbag REQUIRED)
add_library(amigobot_tracking_ros_report src/ros/recorded_run.cpp)
target_link_libraries(amigobot_tracking_ros_report amigobot_tracking_sim amigobot_tracking_core)
target_compile_options(amigobot_tracking_ros_report PRIVATE ${AMIGOBOT_WARNINGS})
add_dependencies(amigobot_tracking_ros_report ${PROJECT_NAME}_generate_messages_cpp)
install(TARGETS amigobot_tracking_ros_report LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
amigobot_add_tool(run_report src/ros/nodes/run_report.cpp)
target_include_directories(run_report SYSTEM PRIVATE ${rosbag_INCLUDE_DIRS})
target_link_libraries(run_report amigobot_tracking_ros_report amigobot_tracking_aria ${rosbag_LIBRARIES} ${catkin_LIBRARIES})

if(CATKIN_ENABLE_TESTING)
  amigobot_add_unit_test(test_recorded_run test/unit/test_recorded_run.cpp)
  target_link_libraries(test_recorded_run amigobot_tracking_ros_report ${catkin_LIBRARIES})
endif()

# issue 6: every launch file passes roslaunch's checks (nodes resolve to executables,
# parameters load), and sim.launch really runs.
if(CATKIN_ENABLE_TESTING)
  set(check_launch /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/check_launch.py ${PROJECT_SOURCE_DIR}/launch)
  amigobot_add_check(launch_amigobot ${check_launch}/amigobot.launch)
  amigobot_add_check(launch_amigobot_args ${check_launch}/amigobot.launch port:=/dev/ttyACM0 controller:=sim laser_x:=0.2 virtual_obstacles:=${PROJECT_SOURCE_DIR}/config/virtual_obstacles.yaml)
  amigobot_add_check(launch_amigobot_driver ${check_launch}/amigobot_driver.launch)
  amigobot_add_check(launch_sim ${check_launch}/sim.launch)
  amigobot_add_check(launch_sim_pty_rviz ${check_launch}/sim.launch pty:=/tmp/amigobot controller:=sim rviz:=true tracking_params:=${PROJECT_SOURCE_DIR}/config/demo_tracking.yaml)
  amigobot_add_check(launch_two_robots ${check_launch}/two_robots.launch)
  amigobot_add_check(launch_rviz ${check_launch}/rviz.launch ns:=tracker)
  add_rostest(test/rostest/sim_launch.test DEPENDENCIES amigobot_emulator sim_laser ground_truth_localization trail_publisher reference_publisher tracking_node amigobot_tracking_ros amigobot_tracking_ros_driver)
endif()

# The shipped rviz display under Xvfb shows the rho circle, the offset point and a virtual
# obstacle (checked by colour against a baseline screenshot; screenshots in build/rviz_check).
if(CATKIN_ENABLE_TESTING)
  amigobot_add_check(rviz_markers_visible /usr/bin/python3 ${PROJECT_SOURCE_DIR}/test/rviz/check_rviz_markers.py
    --ws ${CATKIN_DEVEL_PREFIX}/.. --out ${CMAKE_BINARY_DIR}/rviz_check)
endif()
