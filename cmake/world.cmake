# Layer 2, world: the world file (walls and disks of an emulated room, the robot's start) that
# the emulators, the simulated sensors and the reports share, and ray casting against it.
# Core + yaml-cpp.
amigobot_add_library(amigobot_tracking_world src/world/world.cpp src/world/raycast.cpp)
target_include_directories(amigobot_tracking_world PUBLIC include)
target_link_libraries(amigobot_tracking_world PUBLIC amigobot_tracking_core yaml-cpp)

if(CATKIN_ENABLE_TESTING)
  amigobot_add_unit_test(test_world test/unit/test_world.cpp)
  target_link_libraries(test_world amigobot_tracking_world)
  target_compile_definitions(test_world PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  amigobot_add_unit_test(test_raycast test/unit/test_raycast.cpp)
  target_link_libraries(test_raycast amigobot_tracking_world)
endif()
