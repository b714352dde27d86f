# Layer 3, ros: the one ROS parameter reader (every ROS library and node reads its field
# tables through it) and the one dynamic_reconfigure mapping over any field table, the tracking nodelet amigobot_tracking/Tracking and tracking_node over
# the core, and the reference publisher (a target for simulation and the demo).
# The master watch and the guarded tf listener are here too: every process of the stack uses them.
amigobot_add_library(amigobot_tracking_ros_params src/ros/param_reader.cpp src/ros/param_aliases.cpp src/ros/reconfigure_mapping.cpp
  src/ros/xmlrpc_call.cpp src/ros/master_watch.cpp src/ros/guarded_tf_listener.cpp src/ros/robot_source.cpp
  src/ros/node_command_line.cpp)
target_link_libraries(amigobot_tracking_ros_params amigobot_tracking_core amigobot_tracking_aria CLI11::CLI11 ${catkin_LIBRARIES})

amigobot_add_library(amigobot_tracking_ros
  src/ros/conversions.cpp
  src/ros/markers.cpp
  src/ros/tracking_params.cpp
  src/ros/tracking_node.cpp
  src/ros/tracking_node_outputs.cpp
  src/ros/virtual_obstacle_interface.cpp
  src/ros/laser_obstacles.cpp
  src/ros/tracking_statistics.cpp
  src/ros/tracking_nodelet.cpp
)
target_include_directories(amigobot_tracking_ros SYSTEM PRIVATE ${urdfdom_INCLUDE_DIRS})
target_link_libraries(amigobot_tracking_ros amigobot_tracking_core amigobot_tracking_ros_params ${catkin_LIBRARIES} ${urdfdom_LIBRARIES})
add_dependencies(amigobot_tracking_ros ${PROJECT_NAME}_generate_messages_cpp ${PROJECT_NAME}_gencfg)

amigobot_add_tool(tracking_node src/ros/programs/tracking_node_main.cpp)
target_link_libraries(tracking_node amigobot_tracking_ros)
amigobot_add_tool(reference_publisher src/ros/programs/reference_publisher.cpp)
target_link_libraries(reference_publisher amigobot_tracking_ros)

if(CATKIN_ENABLE_TESTING)
  foreach(unit tracking_params conversions markers rate_monitor master_presence)
    amigobot_add_unit_test(test_${unit} test/unit/test_${unit}.cpp)
    target_link_libraries(test_${unit} amigobot_tracking_ros)
  endforeach()
  # The rostests of the nodelet and the parameter reader (tracking_nodelet.test,
  # tracking_bad_param.test, param_reader.test, nodelets_extreme_params.test): cmake/rostests.cmake.
  # Every table field in config/*.yaml (with its comment), the README's tables and cfg/*.cfg.
  amigobot_add_unit_test(test_param_coverage test/unit/test_param_coverage.cpp)
  target_link_libraries(test_param_coverage amigobot_tracking_ros amigobot_tracking_ros_driver amigobot_tracking_ros_laser amigobot_tracking_localization)
  # (and config/teleop.yaml: cmake/teleop.cmake links the teleop tables in)
  target_compile_definitions(test_param_coverage PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
