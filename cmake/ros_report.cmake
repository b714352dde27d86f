# Layer 3, ros: run_report scores a recorded run (rosbag) like the offline simulator (make demo).
amigobot_add_library(amigobot_tracking_ros_report src/ros/recorded_run.cpp src/ros/localization_error.cpp)
target_link_libraries(amigobot_tracking_ros_report amigobot_tracking_sim amigobot_tracking_world amigobot_tracking_core)
add_dependencies(amigobot_tracking_ros_report ${PROJECT_NAME}_generate_messages_cpp)

amigobot_add_tool(run_report src/ros/programs/run_report.cpp)
target_include_directories(run_report SYSTEM PRIVATE ${rosbag_INCLUDE_DIRS})
target_link_libraries(run_report amigobot_tracking_ros_report amigobot_tracking_world ${rosbag_LIBRARIES} ${catkin_LIBRARIES})

if(CATKIN_ENABLE_TESTING)
  amigobot_add_unit_test(test_recorded_run test/unit/test_recorded_run.cpp)
  target_link_libraries(test_recorded_run amigobot_tracking_ros_report ${catkin_LIBRARIES})
  amigobot_add_unit_test(test_localization_error test/unit/test_localization_error.cpp)
  target_link_libraries(test_localization_error amigobot_tracking_ros_report ${catkin_LIBRARIES})
endif()

# What `make demo` runs, as one goal: sim.launch's nodes and nodelets (emulated robot and laser,
# driver, laser, localisation, tracking, reference, trails, world markers; sim_laser for
# laser:=sim), run_report, the Python messages `rostopic pub` needs, the cfg headers. One goal
# and not a list on make's command line: CMake's top-level Makefile is .NOTPARALLEL, so listed
# goals were built one after another (-j2 ran one single-source program at a time).
add_custom_target(amigobot_demo)
add_dependencies(amigobot_demo amigobot_emulator laser_emulator ground_truth_localization reference_publisher world_markers
  trail_publisher sim_laser run_report amigobot_tracking_ros amigobot_tracking_ros_driver amigobot_tracking_ros_laser
  amigobot_tracking_ros_localization ${PROJECT_NAME}_generate_messages ${PROJECT_NAME}_gencfg)
