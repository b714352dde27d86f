# Layer 2, sensors: the lasers' own protocols (SCIP 2.0, CoLa-A, RPLIDAR), the laser emulator and the
# ROS-free laser driver over MRPT. Core + world + MRPT; no ROS.
amigobot_add_library(amigobot_tracking_sensors
  src/sensors/scip.cpp
  src/sensors/cola_a.cpp
  src/sensors/laser_model.cpp
  src/sensors/laser_registry.cpp
  src/sensors/laser_session.cpp
  src/sensors/scan_source.cpp
  src/sensors/laser_emulator_server.cpp
  src/sensors/hokuyo_device.cpp
  src/sensors/cola_device.cpp
  src/sensors/cola_session.cpp
  src/sensors/rplidar.cpp
  src/sensors/rplidar_session.cpp
  src/sensors/rplidar_device.cpp
  src/sensors/laser_driver.cpp
  src/sensors/scip_protocol.cpp
  src/sensors/scip_session.cpp
  src/sensors/cola_protocol.cpp
  src/sensors/rplidar_protocol.cpp
)
target_include_directories(amigobot_tracking_sensors PUBLIC include)
target_link_libraries(amigobot_tracking_sensors PUBLIC amigobot_tracking_core amigobot_tracking_world amigobot_tracking_link mrpt::comms mrpt::hwdrivers)

amigobot_add_tool(laser_emulator src/tools/laser_emulator.cpp)
target_link_libraries(laser_emulator amigobot_tracking_sensors amigobot_tracking_aria amigobot_tracking_world)

if(CATKIN_ENABLE_TESTING)
  # The encoders against the specifications' examples, the sessions' conversations.
  foreach(unit scip cola_a laser_session laser_registry rplidar)
    amigobot_add_unit_test(test_sensors_${unit} test/unit/test_sensors_${unit}.cpp)
    target_link_libraries(test_sensors_${unit} amigobot_tracking_sensors)
  endforeach()
endif()

if(CATKIN_ENABLE_TESTING)
  # The driver against the emulator executable over real TCP sockets and real ptys, by device.
  foreach(device driver lms1xx rplidar)
    amigobot_add_unit_test(test_sensors_${device}_emulator test/integration/test_sensors_${device}_emulator.cpp)
    target_link_libraries(test_sensors_${device}_emulator amigobot_tracking_sensors)
    target_compile_definitions(test_sensors_${device}_emulator PRIVATE AMIGOBOT_LASER_EMULATOR="$<TARGET_FILE:laser_emulator>")
    add_dependencies(test_sensors_${device}_emulator laser_emulator)
  endforeach()
endif()

if(CATKIN_ENABLE_TESTING)
  # The standard drivers' conversations (urg_c, clearpath LMS1xx, sick_tim, Slamtec's SDK),
  # replayed byte for byte against the emulator executable, their replies parsed as they do.
  foreach(suite standard_drivers rplidar_sdk)
    amigobot_add_unit_test(test_sensors_${suite} test/integration/test_sensors_${suite}.cpp)
    target_link_libraries(test_sensors_${suite} amigobot_tracking_sensors)
    target_compile_definitions(test_sensors_${suite} PRIVATE AMIGOBOT_LASER_EMULATOR="$<TARGET_FILE:laser_emulator>")
    add_dependencies(test_sensors_${suite} laser_emulator)
  endforeach()
endif()
