# Layer 2: the ARIA robot protocol, the MRPT-based driver library and the robot emulator.
# Core + MRPT (comms, poses) + yaml-cpp; no ROS headers.
find_package(mrpt-comms REQUIRED)
find_package(mrpt-poses REQUIRED)
find_package(Threads REQUIRED)

add_library(amigobot_tracking_aria
  src/aria/packet.cpp
  src/aria/commands.cpp
  src/aria/sip.cpp
  src/aria/robot_params.cpp
  src/aria/odometry.cpp
  src/aria/wheel_command.cpp
  src/aria/transport.cpp
  src/aria/client.cpp
  src/aria/client_config.cpp
  src/aria/emulator.cpp
  src/aria/emulator_options.cpp
  src/aria/emulator_server.cpp
)
target_include_directories(amigobot_tracking_aria PUBLIC include)
target_link_libraries(amigobot_tracking_aria PUBLIC amigobot_tracking_core mrpt::comms mrpt::poses yaml-cpp Threads::Threads)
target_compile_options(amigobot_tracking_aria PRIVATE ${AMIGOBOT_WARNINGS})

amigobot_add_tool(amigobot_emulator src/tools/amigobot_emulator.cpp)
target_link_libraries(amigobot_emulator amigobot_tracking_aria)
amigobot_add_tool(amigobot_drive src/tools/amigobot_drive.cpp)
target_link_libraries(amigobot_drive amigobot_tracking_aria)
amigobot_add_tool(aria_command_study src/tools/aria_command_study.cpp)
target_link_libraries(aria_command_study amigobot_tracking_aria)

# `make bench`: figures of the ARIA layer (parser throughput, quantisation).
find_package(benchmark QUIET)
if(benchmark_FOUND)
  add_executable(bench_aria test/bench/bench_aria.cpp)
  target_link_libraries(bench_aria amigobot_tracking_aria benchmark::benchmark)
  target_compile_options(bench_aria PRIVATE ${AMIGOBOT_WARNINGS})
  set_target_properties(bench_aria PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})
endif()
