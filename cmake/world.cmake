# Layer 2, world: the world file (walls and disks of an emulated room, the robot's start) that
# the emulators, the simulated sensors and the reports share, and ray casting against it.
# Core + yaml-cpp.
amigobot_add_library(amigobot_tracking_world src/world/world.cpp src/world/geometry.cpp src/world/raycast.cpp)
target_include_directories(amigobot_tracking_world PUBLIC include)
target_link_libraries(amigobot_tracking_world PUBLIC amigobot_tracking_core yaml-cpp)

amigobot_add_benchmark(bench_world test/bench/bench_world.cpp amigobot_tracking_world)
if(TARGET bench_world)
  target_compile_definitions(bench_world PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

if(CATKIN_ENABLE_TESTING)
  amigobot_add_unit_test(test_world test/unit/test_world.cpp)
  target_link_libraries(test_world amigobot_tracking_world)
  target_compile_definitions(test_world PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  foreach(unit raycast world_geometry world_people tracker_on_scans)
    amigobot_add_unit_test(test_${unit} test/unit/test_${unit}.cpp)
    target_link_libraries(test_${unit} amigobot_tracking_world)
  endforeach()
endif()
