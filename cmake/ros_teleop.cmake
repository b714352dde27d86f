# Layer ros over teleop: the two nodes keyboard_teleop and joystick_teleop.
amigobot_add_library(amigobot_tracking_ros_teleop src/ros/teleop_node.cpp)
target_link_libraries(amigobot_tracking_ros_teleop amigobot_tracking_teleop amigobot_tracking_ros amigobot_tracking_ros_params ${catkin_LIBRARIES})

amigobot_add_tool(keyboard_teleop src/ros/programs/keyboard_teleop.cpp)
target_link_libraries(keyboard_teleop amigobot_tracking_ros_teleop)
amigobot_add_tool(joystick_teleop src/ros/programs/joystick_teleop.cpp)
target_link_libraries(joystick_teleop amigobot_tracking_ros_teleop)

# Their rostests (keyboard_teleop_*.test, joystick_teleop_*.test): cmake/rostests.cmake.

if(CATKIN_ENABLE_TESTING)
  # test_param_coverage (cmake/ros_tracking.cmake) checks config/teleop.yaml against these tables.
  target_link_libraries(test_param_coverage amigobot_tracking_teleop)
endif()

# param_tables: every node's field table as JSON, read by scripts/tools/param_docs.py (`make docs`
# writes the YAML comments, docs tables and .cfg files from it; the check below fails on a stale one).
amigobot_add_tool(param_tables src/ros/programs/param_tables.cpp)
target_link_libraries(param_tables amigobot_tracking_ros amigobot_tracking_ros_driver amigobot_tracking_ros_laser
                      amigobot_tracking_localization amigobot_tracking_teleop nlohmann_json::nlohmann_json)
