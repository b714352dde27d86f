# Layer ros over teleop: the two nodes keyboard_teleop and joystick_teleop and their rostests.
amigobot_add_library(amigobot_tracking_ros_teleop src/ros/teleop_node.cpp)
target_link_libraries(amigobot_tracking_ros_teleop amigobot_tracking_teleop amigobot_tracking_ros amigobot_tracking_ros_params ${catkin_LIBRARIES})

amigobot_add_tool(keyboard_teleop src/ros/programs/keyboard_teleop.cpp)
target_link_libraries(keyboard_teleop amigobot_tracking_ros_teleop)
amigobot_add_tool(joystick_teleop src/ros/programs/joystick_teleop.cpp)
target_link_libraries(joystick_teleop amigobot_tracking_ros_teleop)

if(CATKIN_ENABLE_TESTING)
  # The nodes as child processes of the test (a pseudo-terminal for the keyboard, a FIFO of
  # js_event records for the joystick), one behaviour per .test.
  amigobot_add_rostest_gtest(test_keyboard_teleop test/rostest/keyboard_teleop_keys.test test/rostest/test_keyboard_teleop.cpp)
  target_compile_definitions(test_keyboard_teleop PRIVATE KEYBOARD_TELEOP="$<TARGET_FILE:keyboard_teleop>")
  add_dependencies(test_keyboard_teleop keyboard_teleop)
  foreach(behaviour timeout sigint refusals)
    add_rostest(test/rostest/keyboard_teleop_${behaviour}.test DEPENDENCIES test_keyboard_teleop)
  endforeach()
  amigobot_add_rostest_gtest(test_joystick_teleop test/rostest/joystick_teleop_deadman.test test/rostest/test_joystick_teleop.cpp)
  target_compile_definitions(test_joystick_teleop PRIVATE JOYSTICK_TELEOP="$<TARGET_FILE:joystick_teleop>")
  add_dependencies(test_joystick_teleop joystick_teleop)
  add_rostest(test/rostest/joystick_teleop_device_lost.test DEPENDENCIES test_joystick_teleop)
endif()

if(CATKIN_ENABLE_TESTING)
  # test_param_coverage (cmake/ros_tracking.cmake) checks config/teleop.yaml against these tables.
  target_link_libraries(test_param_coverage amigobot_tracking_teleop)
endif()

# param_tables: every node's field table as JSON, read by scripts/tools/param_docs.py (`make docs`
# writes the YAML comments, docs tables and .cfg files from it; the check below fails on a stale one).
amigobot_add_tool(param_tables src/ros/programs/param_tables.cpp)
target_link_libraries(param_tables amigobot_tracking_ros amigobot_tracking_ros_driver amigobot_tracking_ros_laser
                      amigobot_tracking_localization amigobot_tracking_teleop nlohmann_json::nlohmann_json)
