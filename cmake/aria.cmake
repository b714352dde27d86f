# Layer 2, aria: the ARIA robot protocol, the MRPT-based driver library and the robot
# emulator. Core + world + MRPT (comms, poses) + yaml-cpp; no ROS.
amigobot_add_library(amigobot_tracking_aria
  src/aria/packet.cpp
  src/aria/commands.cpp
  src/aria/sip.cpp
  src/aria/robot_params.cpp
  src/aria/odometry.cpp
  src/aria/wheel_command.cpp
  src/aria/transport.cpp
  src/aria/client.cpp
  src/aria/client_config.cpp
  src/aria/client_handshake.cpp
  src/aria/client_firmware.cpp
  src/aria/client_limits.cpp
  src/aria/client_acknowledgement.cpp
  src/aria/acknowledgement_watch.cpp
  src/aria/emulator.cpp
  src/aria/emulator_options.cpp
  src/aria/emulator_sip.cpp
  src/aria/emulator_server.cpp
  src/aria/emulator_line.cpp
  src/aria/emulator_status.cpp
)
target_include_directories(amigobot_tracking_aria PUBLIC include)
target_link_libraries(amigobot_tracking_aria PUBLIC amigobot_tracking_core amigobot_tracking_world amigobot_tracking_link mrpt::comms mrpt::poses yaml-cpp Threads::Threads)

amigobot_add_tool(amigobot_emulator src/tools/amigobot_emulator.cpp)
target_link_libraries(amigobot_emulator amigobot_tracking_aria amigobot_tracking_world)
amigobot_add_tool(amigobot_drive src/tools/amigobot_drive.cpp)
target_link_libraries(amigobot_drive amigobot_tracking_aria)
amigobot_add_tool(aria_command_study src/tools/aria_command_study.cpp)
target_link_libraries(aria_command_study amigobot_tracking_aria)

if(CATKIN_ENABLE_TESTING)
  # Codec, parameters, quantisation, odometry, emulator.
  foreach(unit packet sip robot_params wheel_command odometry emulator emulator_line emulator_firmware client_config connect_error_text
               acknowledgement_watch)
    amigobot_add_unit_test(test_aria_${unit} test/unit/test_aria_${unit}.cpp)
    target_link_libraries(test_aria_${unit} amigobot_tracking_aria)
    target_compile_definitions(test_aria_${unit} PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  endforeach()
  # The driver library against the emulator executable over real TCP sockets and a real pty.
  amigobot_add_unit_test(test_aria_driver_emulator test/integration/test_aria_driver_emulator.cpp)
  target_link_libraries(test_aria_driver_emulator amigobot_tracking_aria)
  target_compile_definitions(test_aria_driver_emulator PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
  add_dependencies(test_aria_driver_emulator amigobot_emulator)
  # The status protocol: writer, parser, and the client's reconnect against the real emulator.
  amigobot_add_unit_test(test_aria_baud test/integration/test_aria_baud.cpp)
  target_link_libraries(test_aria_baud amigobot_tracking_aria)
  target_compile_definitions(test_aria_baud PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
  add_dependencies(test_aria_baud amigobot_emulator)

  amigobot_add_unit_test(test_aria_emulator_status test/unit/test_aria_emulator_status.cpp)
  target_link_libraries(test_aria_emulator_status amigobot_tracking_aria)
  target_compile_definitions(test_aria_emulator_status PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
  add_dependencies(test_aria_emulator_status amigobot_emulator)

  # One command sequence through the emulator's firmware and the simulator's body: one trajectory.
  amigobot_add_unit_test(test_actuator_parity test/unit/test_actuator_parity.cpp)
  target_link_libraries(test_actuator_parity amigobot_tracking_aria amigobot_tracking_sim)
  # amigobot_sim --identify's fitter on emulator runs with non-default firmware values.
  amigobot_add_unit_test(test_actuator_fit test/unit/test_actuator_fit.cpp)
  target_link_libraries(test_actuator_fit amigobot_tracking_aria amigobot_tracking_sim)
endif()

# The libFuzzer target of the packet parser is built by scripts/test/run_fuzz.sh with clang.
amigobot_add_benchmark(bench_aria test/bench/bench_aria.cpp amigobot_tracking_aria)
