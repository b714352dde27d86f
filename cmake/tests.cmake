# gtest units, one file per unit of the core (later: codec, rostest).
function(amigobot_add_unit_test name)
  catkin_add_gtest(${name} ${ARGN})
  target_link_libraries(${name} ${GTEST_MAIN_LIBRARIES})
  target_compile_options(${name} PRIVATE ${AMIGOBOT_WARNINGS})
endfunction()

amigobot_add_unit_test(test_diamond test/unit/test_diamond.cpp)
target_link_libraries(test_diamond amigobot_tracking_core)
amigobot_add_unit_test(test_estimator test/unit/test_estimator.cpp)
target_link_libraries(test_estimator amigobot_tracking_core)
amigobot_add_unit_test(test_offset_point test/unit/test_offset_point.cpp)
target_link_libraries(test_offset_point amigobot_tracking_core)
amigobot_add_unit_test(test_avoidance test/unit/test_avoidance.cpp)
target_link_libraries(test_avoidance amigobot_tracking_core)
amigobot_add_unit_test(test_controller_config test/unit/test_controller_config.cpp)
target_link_libraries(test_controller_config amigobot_tracking_core)
amigobot_add_unit_test(test_closed_loop test/unit/test_closed_loop.cpp)
target_link_libraries(test_closed_loop amigobot_tracking_core)

# A command run as one JUnit test case (scripts/junit_check.py writes the XML the counter reads).
# catkin's runner takes the command as one string.
function(amigobot_add_check name)
  string(REPLACE ";" " " command "${ARGN}")
  catkin_run_tests_target("check" ${name} "check-${name}.xml"
    COMMAND "/usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/junit_check.py --name ${name} --xml ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/check-${name}.xml -- ${command}")
endfunction()

amigobot_add_check(urdf_parses check_urdf ${PROJECT_SOURCE_DIR}/urdf/amigobot.urdf)
amigobot_add_unit_test(test_beyond_paper test/unit/test_beyond_paper.cpp)
target_link_libraries(test_beyond_paper amigobot_tracking_core)
amigobot_add_unit_test(test_obstacle_tracker test/unit/test_obstacle_tracker.cpp)
target_link_libraries(test_obstacle_tracker amigobot_tracking_core)
amigobot_add_unit_test(test_raycast test/unit/test_raycast.cpp)
target_link_libraries(test_raycast amigobot_tracking_core)
