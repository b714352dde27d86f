# Layer 1, link: the byte links every device shares: the one host:port rule, the serial
# opener (raw 8N1, any baud) and the server side of an emulated device (one-client TCP port,
# pty behind a symlink). Standard library + POSIX only: no core, no MRPT, no ROS.
amigobot_add_library(amigobot_tracking_link
  src/link/address.cpp
  src/link/serial_port.cpp
  src/link/emulator_link.cpp
  src/link/system_clock_errors.cpp
  src/link/tcp_client.cpp
)
target_include_directories(amigobot_tracking_link PUBLIC include)

if(CATKIN_ENABLE_TESTING)
  foreach(unit address serial_port tcp_client line_clients)
    amigobot_add_unit_test(test_link_${unit} test/unit/test_link_${unit}.cpp)
    target_link_libraries(test_link_${unit} amigobot_tracking_link)
  endforeach()
endif()
