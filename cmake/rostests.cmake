# The gtest rostests under test/rostest/: ONE executable, test_rostest, runs them all; each
# .test file starts it with a --gtest_filter choosing its own cases (as test_e2e does for the
# end-to-end tier). Why one: a source's translation unit is mostly the gtest, ROS, MRPT and Eigen
# headers it includes, so 13 executables of one or two sources parsed the same headers 14 times
# and linked 13 times; built as one in unity batches (amigobot_unity_build) they are parsed once
# per batch and linked once (docs/testing.md gives the figures). So its sources are compiled
# together: each keeps its cases in a namespace of its own (file-scope names and
# using-directives would clash in a batch). One main for every run
# (test/rostest/test_rostest_main.cpp): ROS, a 2-thread spinner and the NaN watcher; a case that
# needs more (the tracking nodelet's scripted world) sets it up in its own fixture.
if(NOT CATKIN_ENABLE_TESTING)
  return()
endif()
add_executable(test_rostest EXCLUDE_FROM_ALL
  test/rostest/test_rostest_main.cpp
  test/rostest/test_localization_tracking.cpp
  test/rostest/test_localization_mapping.cpp
  test/rostest/test_localization_bad_param.cpp
  test/rostest/test_localization_bad_scans.cpp
  test/rostest/test_laser_ros.cpp
  test/rostest/test_driver_ros.cpp
  test/rostest/test_driver_one_way_link.cpp
  test/rostest/test_tracking_nodelet.cpp
  test/rostest/test_tracking_param_loading.cpp
  test/rostest/test_tracking_bad_param.cpp
  test/rostest/test_param_reader.cpp
  test/rostest/test_nodelets_extreme_params.cpp
  test/rostest/test_keyboard_teleop.cpp
  test/rostest/test_joystick_teleop.cpp)
# The param reader's cases read every node's tables; the driver, laser and localisation cases
# load their nodelet in-process (pluginlib finds the library already linked) and judge it with
# the layers below.
target_link_libraries(test_rostest amigobot_tracking_ros amigobot_tracking_ros_driver amigobot_tracking_ros_laser
                      amigobot_tracking_ros_localization amigobot_tracking_aria amigobot_tracking_sensors
                      amigobot_tracking_localization amigobot_tracking_world ${catkin_LIBRARIES} ${GTEST_LIBRARIES})
target_include_directories(test_rostest SYSTEM PRIVATE ${GTEST_INCLUDE_DIRS})
target_include_directories(test_rostest PRIVATE test/support test/e2e/include)
# The programs the cases start as child processes.
target_compile_definitions(test_rostest PRIVATE
  AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>"
  AMIGOBOT_LASER_EMULATOR="$<TARGET_FILE:laser_emulator>"
  AMIGOBOT_LOCALIZATION_NODE="$<TARGET_FILE:localization_node>"
  KEYBOARD_TELEOP="$<TARGET_FILE:keyboard_teleop>"
  JOYSTICK_TELEOP="$<TARGET_FILE:joystick_teleop>")
# A fixture in a source's anonymous namespace is a base of its TEST classes: in a unity batch the
# source is an included file, which GCC flags (-Wsubobject-linkage) though nothing leaks.
target_compile_options(test_rostest PRIVATE ${AMIGOBOT_TEST_OPTIONS} -Wno-subobject-linkage)
amigobot_unity_build(test_rostest)
add_dependencies(test_rostest ${PROJECT_NAME}_generate_messages_cpp  # nan_watcher.h judges TrackingState
                 amigobot_emulator laser_emulator localization_node keyboard_teleop joystick_teleop)
add_dependencies(tests test_rostest)

# What each .test runs: tracking_nodelet, the tracking nodelet in a real nodelet manager with a
# scripted world, and the tracking parameter loaders against the master; localization_*, the
# Localization nodelet in the test's process on a synthetic room (the test publishes the scans
# and odom -> base_footprint): on its map, mapping it, bad parameters (and the standalone node
# with a missing map, 20 times), bad scans; laser, the Laser nodelet against the laser emulator
# executable; driver, the driver nodelet against the emulator executable on a free port, and
# driver_one_way_link, the emulator's control socket cutting the driver -> robot direction,
# which the driver names; keyboard_teleop_* and joystick_teleop_*, the teleop nodes as child
# processes (a pseudo-terminal for the keyboard, a FIFO of js_event records for the joystick),
# one behaviour each; tracking_bad_param, a bad parameter starts nothing; nodelets_extreme_params,
# every nodelet with extreme in-bounds parameters in one manager that must survive; param_reader,
# the parameter reader (types checked, ints for reals, errors naming the parameter, other
# drivers' names as aliases).
# Longest first (make starts the run_tests targets in the order they are declared); seconds of
# one run on 2 shared cores.
foreach(file
    laser                         # 31
    localization_bad_param        # 20
    tracking_nodelet              # 20
    localization_mapping          # 17
    localization_tracking         # 17
    driver_one_way_link           # 16
    driver                        # 11
    keyboard_teleop_keys          # 11
    tracking_bad_param            # 11
    localization_bad_scans        # 11
    nodelets_extreme_params       # 8
    keyboard_teleop_timeout       # 7
    joystick_teleop_deadman       # 7
    keyboard_teleop_sigint        # 6
    joystick_teleop_device_lost   # 6
    param_reader                  # 5
    keyboard_teleop_refusals)     # 5
  add_rostest(test/rostest/${file}.test DEPENDENCIES test_rostest)
endforeach()
# Every case of test_rostest is selected by some .test file's filter, and every filter selects a
# case: a case in a new suite that no filter names would otherwise never run, silently.
amigobot_add_check(rostest_filters_cover_cases ${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/check_gtest_filters.py
                   ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/test_rostest ${PROJECT_SOURCE_DIR}/test/rostest)
