# Plain CMake without catkin (-DAMIGOBOT_ROS=OFF): the ROS-free layers (core, world, sim,
# sim_mrpt, aria, sensors, localization, teleop), their tools and their gtest units, run by
# ctest — for a user of the controller or the device libraries who has no ROS (as kobuki_core
# builds without ROS). catkin's folder variables and its gtest function get plain stand-ins, so
# the library fragments are the same files in both builds.
#   cmake -S . -B ../amigobot_core_build -DAMIGOBOT_ROS=OFF && cmake --build ../amigobot_core_build -j2
#   ctest --test-dir ../amigobot_core_build
# (Build outside the package: rosrun walks the package's folder and would find the copies.)
set(CATKIN_DEVEL_PREFIX ${CMAKE_BINARY_DIR})
set(CATKIN_PACKAGE_BIN_DESTINATION lib/${PROJECT_NAME})
set(CATKIN_PACKAGE_LIB_DESTINATION lib)
set(CATKIN_GLOBAL_BIN_DESTINATION bin)
set(CATKIN_PACKAGE_INCLUDE_DESTINATION include/${PROJECT_NAME})
set(CATKIN_PACKAGE_SHARE_DESTINATION share/${PROJECT_NAME})
option(BUILD_TESTING "build the gtest units (ctest runs them)" ON)
set(CATKIN_ENABLE_TESTING ${BUILD_TESTING})
if(CATKIN_ENABLE_TESTING)
  enable_testing()
  find_package(GTest REQUIRED)
  set(GTEST_LIBRARIES GTest::gtest)
  set(GTEST_MAIN_LIBRARIES GTest::gtest_main)
  # catkin_add_gtest's contract as the fragments use it: an executable linked with gtest, one test.
  function(catkin_add_gtest name)
    add_executable(${name} ${ARGN})
    target_link_libraries(${name} GTest::gtest)
    add_test(NAME ${name} COMMAND ${name})
  endfunction()
endif()
