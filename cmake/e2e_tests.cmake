# End-to-end rostests: the whole stack (driver and tracking nodelets, sim_laser,
# ground_truth_localization, robot_state_publisher) on amigobot_emulator, judged from the
# emulator's ground truth and command log by one gtest executable; each .test file under
# test/e2e runs one of its cases. Ports: scripts/test/with_free_ports.py appends NAME:=PORT for
# each port arg the .test file declares, just before rostest starts.
if(NOT CATKIN_ENABLE_TESTING)
  return()
endif()
find_program(AMIGOBOT_ROSTEST rostest)
if(NOT AMIGOBOT_ROSTEST)
  message(FATAL_ERROR "rostest not found on PATH (the e2e tests run it)")
endif()
add_executable(test_e2e EXCLUDE_FROM_ALL test/e2e/test_e2e.cpp test/e2e/test_bad_parameters.cpp
  test/e2e/test_target_loss.cpp test/e2e/test_link_loss.cpp test/e2e/test_avoidance.cpp test/e2e/test_two_robots.cpp
  test/e2e/test_fault_injection.cpp test/e2e/test_wrong_initial_pose.cpp test/e2e/test_laser_faults.cpp
  test/e2e/test_cpu_starvation.cpp test/e2e/test_kidnap.cpp
  test/e2e/test_bad_scans.cpp test/e2e/test_bad_virtual_obstacles.cpp test/e2e/test_person_crossing.cpp)
target_link_libraries(test_e2e amigobot_tracking_ros_sim amigobot_tracking_world ${catkin_LIBRARIES} ${GTEST_LIBRARIES})
target_include_directories(test_e2e SYSTEM PRIVATE ${GTEST_INCLUDE_DIRS})
target_include_directories(test_e2e PRIVATE test/support test/e2e/include)
target_compile_definitions(test_e2e PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
target_compile_options(test_e2e PRIVATE ${AMIGOBOT_TEST_OPTIONS})
amigobot_unity_build(test_e2e)
add_dependencies(test_e2e ${PROJECT_NAME}_generate_messages_cpp)
add_dependencies(tests test_e2e)
# What the e2e tier runs: the demo's stack (amigobot_demo, cmake/ros_report.cmake: the
# emulators, nodelets, sim_laser, ground truth, the reference and trail publishers, the
# messages), the judge and a lab's own laser driver (external_laser.test).
set(AMIGOBOT_E2E_NODES test_e2e laser_node amigobot_demo)
# Everything the e2e tier runs, built in one go (make test-under-load builds it before loading the cores).
add_custom_target(amigobot_e2e_nodes)
add_dependencies(amigobot_e2e_nodes ${AMIGOBOT_E2E_NODES})

# amigobot_add_e2e_test(FILE PORT_ARG...): rostest FILE with a free port for each PORT_ARG.
function(amigobot_add_e2e_test file)
  get_filename_component(name ${file} NAME_WE)
  set(cmd "${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/with_free_ports.py ${ARGN} --"
          "${PYTHON_EXECUTABLE} ${AMIGOBOT_ROSTEST} --pkgdir=${PROJECT_SOURCE_DIR} --package=${PROJECT_NAME}"
          "--results-filename e2e_${name}.xml --results-base-dir \"${CATKIN_TEST_RESULTS_DIR}\""
          "${PROJECT_SOURCE_DIR}/${file}")
  string(REPLACE ";" " " cmd "${cmd}")
  catkin_run_tests_target("rostest" e2e_${name} "rostest-e2e_${name}.xml" COMMAND ${cmd}
                          DEPENDENCIES ${AMIGOBOT_E2E_NODES})
endfunction()

# Every case of test_e2e is run by some .test file, and every .test's filter selects a case.
amigobot_add_check(e2e_filters_cover_cases ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_gtest_filters.py
                   ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/test_e2e ${PROJECT_SOURCE_DIR}/test/e2e)

# Longest first (make starts the run_tests targets in the order they are declared): the
# 2-minute avoidance lap last left one core idle for the last minute of the run.
amigobot_add_e2e_test(test/e2e/avoidance.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/rates.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/person_crossing.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/link_loss.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/bad_scans.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/tracking.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/diamond.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/watchdog.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/target_loss.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/fault_future_stamp.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/fault_future_stamp_then_good.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/fault_second_cmd_vel.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/fault_wrong_initial_pose.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/fault_laser_stall.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/fault_laser_kill.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/fault_laser_blind.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/fault_laser_halved.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/fault_cpu_starvation.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/fault_kidnap.test tcp_port status_port laser_port control_port)
amigobot_add_e2e_test(test/e2e/bad_parameters.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/bad_parameter_types.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/bad_virtual_obstacles.test tcp_port status_port)
amigobot_add_e2e_test(test/e2e/virtual_obstacle_burst.test tcp_port status_port)
# laser:=none with the lab's own driver (a standalone laser_node) on /front_laser/scan; judged in Python.
amigobot_add_e2e_test(test/e2e/external_laser.test tcp_port status_port laser_port)
amigobot_add_e2e_test(test/e2e/two_robots.test target_tcp_port target_status_port tracker_tcp_port tracker_status_port
                      target_laser_port tracker_laser_port)
# The ROS master killed while tracking and restarted on the same port (its own roscore, so not
# a rostest): the driver stops, everything registers with the new master, services and
# cmd_vel work again. Judged from the emulator's ground truth and journal (Python).
amigobot_add_check(e2e_master_restart ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/master_restart.py
                   --logs ${CMAKE_BINARY_DIR}/master_restart)
