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
  # Every Makefile target has its one-line `make help` entry (help fails naming one without).
  amigobot_add_check(make_help env -u MAKEFLAGS -u MAKELEVEL make -s -C ${PROJECT_SOURCE_DIR} help)

  set(check_launch ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_launch.py ${PROJECT_SOURCE_DIR}/launch)
  amigobot_add_check(launch_amigobot ${check_launch}/amigobot.launch)
  amigobot_add_check(launch_amigobot_args ${check_launch}/amigobot.launch port:=/dev/ttyACM0 controller:=sim laser_x:=0.2 virtual_obstacles:=${PROJECT_SOURCE_DIR}/config/virtual_obstacles.yaml)
  amigobot_add_check(launch_amigobot_tim ${check_launch}/amigobot.launch laser:=sick_tim5xx laser_port:=192.168.0.1:2111)
  amigobot_add_check(launch_amigobot_urg ${check_launch}/amigobot.launch laser:=hokuyo_urg laser_port:=/dev/ttyACM0 laser_upside_down:=true)
  amigobot_add_check(launch_amigobot_slam ${check_launch}/amigobot.launch laser:=sick_tim5xx laser_port:=192.168.0.1:2111 localization:=slam map_file:=/tmp/lab.yaml)
  amigobot_add_check(launch_amigobot_map ${check_launch}/amigobot.launch laser:=sick_tim5xx laser_port:=192.168.0.1:2111 localization:=map map_file:=${PROJECT_SOURCE_DIR}/config/maps/lab.yaml)
  amigobot_add_check(launch_amigobot_lms ${check_launch}/amigobot.launch laser:=sick_lms1xx laser_port:=192.168.0.1:2111)
  amigobot_add_check(launch_amigobot_rplidar ${check_launch}/amigobot.launch laser:=rplidar laser_port:=/dev/ttyUSB1)
  amigobot_add_check(launch_amigobot_driver ${check_launch}/amigobot_driver.launch)
  amigobot_add_check(launch_sim ${check_launch}/sim.launch)
  amigobot_add_check(launch_sim_hokuyo ${check_launch}/sim.launch laser:=hokuyo_urg)
  amigobot_add_check(launch_sim_tim ${check_launch}/sim.launch laser:=sick_tim5xx laser_port:=10941)
  amigobot_add_check(launch_sim_rplidar ${check_launch}/sim.launch laser:=rplidar)
  amigobot_add_check(launch_two_robots_emulated_lasers ${check_launch}/two_robots.launch target_port:=127.0.0.1:8201 tracker_port:=127.0.0.1:8203
    target_status_port:=8202 tracker_status_port:=8204 target_world:=${PROJECT_SOURCE_DIR}/config/worlds/demo_5_3.yaml
    tracker_world:=${PROJECT_SOURCE_DIR}/config/worlds/demo_5_3.yaml target_laser:=hokuyo_urg tracker_laser:=sick_lms1xx)
  amigobot_add_check(launch_two_robots_real_lasers ${check_launch}/two_robots.launch tracker_laser:=rplidar tracker_laser_port:=/dev/ttyUSB2)
  amigobot_add_check(launch_sim_pty_rviz ${check_launch}/sim.launch pty:=/tmp/amigobot controller:=sim rviz:=true tracking_params:=${PROJECT_SOURCE_DIR}/config/demo_tracking.yaml)
  amigobot_add_check(launch_sim_slam ${check_launch}/sim.launch localization:=slam map_file:=/tmp/new_map.yaml)
  amigobot_add_check(launch_sim_ground_truth ${check_launch}/sim.launch localization:=ground_truth laser:=sim)
  amigobot_add_check(launch_two_robots ${check_launch}/two_robots.launch)
  amigobot_add_check(launch_two_robots_map ${check_launch}/two_robots.launch localization:=map map_file:=${PROJECT_SOURCE_DIR}/config/maps/lab.yaml target_laser:=sick_tim5xx target_laser_port:=192.168.0.2:2111 tracker_laser:=sick_tim5xx tracker_laser_port:=192.168.0.1:2111)
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
  amigobot_add_check(launch_two_robots_teleop ${check_launch}/two_robots.launch target_teleop:=keyboard)
  amigobot_add_check(launch_teleop ${check_launch}/teleop.launch)
  amigobot_add_check(launch_teleop_joystick ${check_launch}/teleop.launch ns:=target device:=/dev/input/js0)
  amigobot_add_check(launch_rviz ${check_launch}/rviz.launch ns:=tracker)
  amigobot_add_check(launch_localization ${check_launch}/include/localization.launch map_file:=/tmp/map.yaml)
  add_rostest(test/rostest/sim_launch.test DEPENDENCIES amigobot_emulator sim_laser ground_truth_localization
              trail_publisher reference_publisher tracking_node amigobot_tracking_ros amigobot_tracking_ros_driver)

  # `catkin_make install` into .ws-install, then sim.launch from that prefix alone.
  amigobot_add_check(install_space ${PROJECT_SOURCE_DIR}/test/install/check_install_space.sh)

  # Under Xvfb (screenshots in build/rviz_check).
  amigobot_add_check(rviz_markers_visible ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/rviz/check_rviz_markers.py
    --ws ${CATKIN_DEVEL_PREFIX}/.. --out ${CMAKE_BINARY_DIR}/rviz_check)
endif()
