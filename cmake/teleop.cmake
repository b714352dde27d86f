# Layer teleop (std, POSIX, linux/joystick.h, core): tele-operation of a robot without ROS —
# the keyboard's keys and the joystick's events mapped onto (v, omega), the raw terminal and
# the joystick device (the two nodes over it, layer ros: cmake/ros_teleop.cmake).
amigobot_add_library(amigobot_tracking_teleop
  src/teleop/keyboard.cpp
  src/teleop/joystick.cpp
  src/teleop/terminal.cpp
  src/teleop/joystick_device.cpp
)
target_link_libraries(amigobot_tracking_teleop amigobot_tracking_core)

if(CATKIN_ENABLE_TESTING)
  foreach(unit teleop_keyboard teleop_joystick)
    amigobot_add_unit_test(test_${unit} test/unit/test_${unit}.cpp)
    target_link_libraries(test_${unit} amigobot_tracking_teleop)
  endforeach()
endif()
