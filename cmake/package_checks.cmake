# Whole-package checks, each one counted test case: the URDF parses, the layers include only
# what they may, the test scripts work, `make help` is complete, every launch file passes
# roslaunch's checks (nodes resolve to executables, parameters load), sim.launch really runs,
# the install space works on its own, and the shipped rviz display shows the markers.
if(CATKIN_ENABLE_TESTING)
  find_program(AMIGOBOT_CHECK_URDF check_urdf)
  if(NOT AMIGOBOT_CHECK_URDF)
    message(FATAL_ERROR "check_urdf not found (apt-get install liburdfdom-tools)")
  endif()
  amigobot_add_check(urdf_parses ${AMIGOBOT_CHECK_URDF} ${PROJECT_SOURCE_DIR}/urdf/amigobot.urdf)

  # Each layer includes only what it may (scripts/test/check_layers.py); the checker and the result
  # counter have their own tests on fixture trees.
  amigobot_add_check(layers ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_layers.py ${PROJECT_SOURCE_DIR})
  amigobot_add_check(check_layers_selftest ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_check_layers.py
                     ${PROJECT_SOURCE_DIR}/scripts/test/check_layers.py)
  amigobot_add_check(count_test_results_selftest ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_count_test_results.py
                     ${PROJECT_SOURCE_DIR}/scripts/test/count_test_results.py)
  # The NaN check of recorded bags (make demo's) on bags it writes, NaN and allowed infinities.
  amigobot_add_check(check_bag_finite_selftest ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_check_bag_finite.py
                     ${PROJECT_SOURCE_DIR}/scripts/test/check_bag_finite.py)
  # The clutter benchmark's report in its quick mode on two classes, with the real simulator.
  amigobot_add_check(clutter_report_quick ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_clutter_report.py
                     ${PROJECT_SOURCE_DIR}/scripts/reports/clutter.py
                     ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/amigobot_sim)
  # The pedestrian benchmark in its quick mode on three classes: every run completes, no NaN, no
  # command outside the diamond.
  amigobot_add_check(pedestrian_report_quick ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_pedestrian_report.py
                     ${PROJECT_SOURCE_DIR}/scripts/reports/pedestrians.py
                     ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/amigobot_sim)
  # No library feature newer than Noetic's toolchain (GCC 9 / libstdc++ 9, Eigen 3.3, Python 3.8):
  # the list and the reason for each are in the script (--list prints them).
  amigobot_add_check(cxx_features_noetic ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_cxx_features.py ${PROJECT_SOURCE_DIR})
  amigobot_add_check(check_cxx_features_selftest ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_check_cxx_features.py
                     ${PROJECT_SOURCE_DIR}/scripts/test/check_cxx_features.py)
  # The udev rules (`make udev`) parse as udev reads them and name /dev/amigobot and /dev/laser.
  amigobot_add_check(udev_rules ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_udev_rules.py
                     ${PROJECT_SOURCE_DIR}/config/udev/99-amigobot.rules)
  amigobot_add_check(check_udev_rules_selftest ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_check_udev_rules.py
                     ${PROJECT_SOURCE_DIR}/scripts/test/check_udev_rules.py)
  # install_deps.sh waits for another package manager's lock, naming it and its holder.
  amigobot_add_check(install_deps_lock_wait ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_install_deps.py
                     ${PROJECT_SOURCE_DIR}/scripts/setup/install_deps.sh)
  # make demo's desktop packages install while it compiles: both at once, each failure kept.
  amigobot_add_check(install_beside_build ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_install_beside.py
                     ${PROJECT_SOURCE_DIR}/scripts/setup/install_beside.sh)
  # Every Makefile target has its one-line `make help` entry (help fails naming one without).
  # The parameter descriptions written from the field tables (`make docs`) are fresh: YAML
  # comments, the docs' parameter tables, the .cfg files (scripts/tools/param_docs.py).
  amigobot_add_check(param_docs_fresh ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/tools/param_docs.py
                     --param-tables ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/param_tables --check ${PROJECT_SOURCE_DIR})
  amigobot_add_check(param_docs_selftest ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/scripts/test_param_docs.py
                     ${PROJECT_SOURCE_DIR}/scripts/tools/param_docs.py)
  amigobot_add_check(make_help env -u MAKEFLAGS -u MAKELEVEL make -s -C ${PROJECT_SOURCE_DIR} help)

  # Every launch configuration of test/launch_checks.txt, in one process, one test case each.
  catkin_run_tests_target("check" launch_files "check-launch_files.xml"
    COMMAND "${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_launch.py --list ${PROJECT_SOURCE_DIR}/test/launch_checks.txt --root ${PROJECT_SOURCE_DIR} --xml ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/check-launch_files.xml")
  # amigobot.launch robot:=NAME: every node, parameter, remapped topic, frame and URDF link of
  # the robot under NAME (the paper's two robots, each on its own computer; docs/real_robot.md).
  amigobot_add_check(launch_namespace_tracker ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_launch_namespace.py
                     ${PROJECT_SOURCE_DIR}/launch/amigobot.launch tracker target_frame:=target/base_footprint laser:=rplidar
                     laser_port:=/dev/laser localization:=map map_file:=${PROJECT_SOURCE_DIR}/config/maps/lab.yaml)
  amigobot_add_check(launch_namespace_target ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_launch_namespace.py
                     ${PROJECT_SOURCE_DIR}/launch/amigobot.launch target tracking:=false laser:=sick_tim5xx
                     laser_port:=192.168.0.2:2111 localization:=map map_file:=${PROJECT_SOURCE_DIR}/config/maps/lab.yaml)
  # Maps: the e2e room's map is world_map's drawing of its world (never stale); the shipped
  # lab map, built by SLAM (`make map`), agrees with the lab world (>= 90 % of its occupied
  # cells within 0.1 m of a wall, table or pole).
  amigobot_add_check(e2e_room_map_fresh ${PROJECT_SOURCE_DIR}/scripts/test/check_world_map.sh
                     ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/world_map
                     ${PROJECT_SOURCE_DIR}/test/e2e/worlds/room.yaml ${PROJECT_SOURCE_DIR}/test/e2e/worlds/room_map.yaml)
  amigobot_add_check(e2e_avoidance_map_fresh ${PROJECT_SOURCE_DIR}/scripts/test/check_world_map.sh
                     ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/world_map
                     ${PROJECT_SOURCE_DIR}/test/e2e/worlds/avoidance.yaml ${PROJECT_SOURCE_DIR}/test/e2e/worlds/avoidance_map.yaml)
  amigobot_add_check(e2e_two_robots_map_fresh ${PROJECT_SOURCE_DIR}/scripts/test/check_world_map.sh
                     ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/world_map
                     ${PROJECT_SOURCE_DIR}/test/e2e/worlds/two_robots_tracker.yaml ${PROJECT_SOURCE_DIR}/test/e2e/worlds/two_robots_map.yaml)
  amigobot_add_check(lab_map_matches_world ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/world_map
                     --world ${PROJECT_SOURCE_DIR}/config/worlds/lab.yaml --compare ${PROJECT_SOURCE_DIR}/config/maps/lab.yaml)
  add_rostest(test/rostest/sim_launch.test DEPENDENCIES amigobot_emulator sim_laser ground_truth_localization
              trail_publisher reference_publisher tracking_node amigobot_tracking_ros amigobot_tracking_ros_driver)
  # Again with the serial-only laser: laser_emulator --endpoint gives it a pty, the driver's
  # laser_emulator:PORT finds it there (the registry's endpoint rule, no name in the launch).
  add_rostest(test/rostest/sim_launch.test ARGS laser:=rplidar status_port:=28773 laser_port:=28774
              DEPENDENCIES amigobot_emulator laser_emulator ground_truth_localization trail_publisher
              reference_publisher tracking_node amigobot_tracking_ros amigobot_tracking_ros_driver)
  # The README's and docs' launch commands, services and topics, read from their text, against the
  # launch files and the quick start's running stack (test/rostest/test_docs_commands.py).
  add_rostest(test/rostest/docs_commands.test DEPENDENCIES amigobot_emulator laser_emulator ground_truth_localization
              trail_publisher reference_publisher tracking_node amigobot_tracking_ros amigobot_tracking_ros_driver)

  # rosrun finds every executable once (no build or install tree inside the package).
  amigobot_add_check(rosrun_finds_each_once ${PROJECT_SOURCE_DIR}/test/install/check_rosrun_unique.sh
                     ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})
  # The built workspace installed (cmake --install, no rebuild), then sim.launch from that prefix alone.
  amigobot_add_check(install_space ${PROJECT_SOURCE_DIR}/test/install/check_install_space.sh ${CMAKE_BINARY_DIR})

  # Under Xvfb (screenshots in build/rviz_check).
  amigobot_add_check(rviz_markers_visible ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/rviz/check_rviz_markers.py
    --ws ${CATKIN_DEVEL_PREFIX}/.. --out ${CMAKE_BINARY_DIR}/rviz_check)
endif()
