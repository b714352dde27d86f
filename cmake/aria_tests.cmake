# gtest units of the aria layer (codec, parameters, quantisation, odometry) and the
# driver <-> emulator tests over real sockets and a real pty.
foreach(unit packet sip robot_params wheel_command odometry emulator client_config)
  amigobot_add_unit_test(test_aria_${unit} test/unit/test_aria_${unit}.cpp)
  target_link_libraries(test_aria_${unit} amigobot_tracking_aria)
  target_compile_definitions(test_aria_${unit} PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endforeach()

# Driver <-> emulator over real TCP sockets and a real pty (the emulator runs as a child).
amigobot_add_unit_test(test_aria_driver_emulator test/aria/test_aria_driver_emulator.cpp)
target_link_libraries(test_aria_driver_emulator amigobot_tracking_aria)
target_include_directories(test_aria_driver_emulator PRIVATE test/aria)
target_compile_definitions(test_aria_driver_emulator PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
add_dependencies(test_aria_driver_emulator amigobot_emulator)

# The status protocol: writer, parser, and the client's reconnect against the real emulator.
amigobot_add_unit_test(test_aria_emulator_status test/unit/test_aria_emulator_status.cpp)
target_link_libraries(test_aria_emulator_status amigobot_tracking_aria)
target_include_directories(test_aria_emulator_status PRIVATE test/aria)
target_compile_definitions(test_aria_emulator_status PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
add_dependencies(test_aria_emulator_status amigobot_emulator)
