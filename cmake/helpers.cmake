# Functions the library fragments use. Included first.

# A thin command-line main over the libraries; `rosrun amigobot_tracking <tool>` finds it
# in devel and in an install space.
function(amigobot_add_tool name)
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} CLI11::CLI11)
  target_compile_options(${name} PRIVATE ${AMIGOBOT_WARNINGS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})
  install(TARGETS ${name} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endfunction()

# Unity builds: a library's sources are compiled AMIGOBOT_UNITY_BATCH at a time as one
# translation unit, so the ROS, MRPT and Eigen headers they share are parsed and their templates
# instantiated once per batch instead of once per source: the demo's targets took 408 CPU-s
# instead of 783 on a cold build (docs/testing.md). So two sources of one library must not define
# the same name in their anonymous namespaces. -DAMIGOBOT_UNITY_BUILD=OFF while editing one source often.
option(AMIGOBOT_UNITY_BUILD "compile each library's sources in batches (CMake unity build)" ON)
set(AMIGOBOT_UNITY_BATCH 8 CACHE STRING "sources per unity translation unit")
function(amigobot_unity_build target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${AMIGOBOT_UNITY_BUILD} UNITY_BUILD_BATCH_SIZE ${AMIGOBOT_UNITY_BATCH})
endfunction()

# A library of the package, installed with its targets (headers: install.cmake).
function(amigobot_add_library name)
  add_library(${name} ${ARGN})
  target_compile_options(${name} PRIVATE ${AMIGOBOT_WARNINGS})
  amigobot_unity_build(${name})
  install(TARGETS ${name}
    ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
    LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
    RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
endfunction()

# A gtest unit (one file per unit under test). Call the test helpers inside
# if(CATKIN_ENABLE_TESTING). The units of one fragment (core.cmake, aria.cmake, ...) compile into
# one executable, test_<fragment>_units, made by amigobot_link_unit_tests() once every fragment
# has given its units their libraries: one link per layer instead of ~90, and with
# AMIGOBOT_UNITY_BUILD their sources compile a batch at a time (gtest, Eigen, MRPT and ROS
# headers parsed once per batch), so two units of one fragment must not define the same name in
# their anonymous namespaces. NAME is a stand-in target that only carries the unit's links,
# definitions and dependencies (target_link_libraries(NAME ...) etc. work as on an executable)
# for the group to take; it is never built. Run one unit with
# test_<fragment>_units --gtest_filter='Suite.*'. Sources under test/integration (each a device
# driven through an emulator for tens of seconds) keep their own executable NAME, so make's jobs
# run them side by side.
function(amigobot_add_unit_test name)
  list(GET ARGN 0 first_source)
  if(first_source MATCHES "^test/integration/")
    catkin_add_gtest(${name} ${ARGN})
    target_link_libraries(${name} ${GTEST_MAIN_LIBRARIES})
    target_compile_options(${name} PRIVATE ${AMIGOBOT_TEST_OPTIONS})
    target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/test/support)
  else()
    add_library(${name} OBJECT EXCLUDE_FROM_ALL ${ARGN})
    get_filename_component(group ${CMAKE_CURRENT_LIST_FILE} NAME_WE)
    set_property(GLOBAL APPEND PROPERTY AMIGOBOT_UNITS_${group} ${name})
    set_property(GLOBAL APPEND PROPERTY AMIGOBOT_UNIT_GROUPS ${group})
  endif()
endfunction()

# One gtest executable per fragment from the sources amigobot_add_unit_test collected, with each
# unit's links, definitions and dependencies (called once: before plain CMake's early return, or
# at the end of the catkin build).
function(amigobot_link_unit_tests)
  if(NOT CATKIN_ENABLE_TESTING)
    return()
  endif()
  get_property(groups GLOBAL PROPERTY AMIGOBOT_UNIT_GROUPS)
  list(REMOVE_DUPLICATES groups)
  foreach(group ${groups})
    get_property(units GLOBAL PROPERTY AMIGOBOT_UNITS_${group})
    set(sources "")
    foreach(unit ${units})
      get_target_property(unit_sources ${unit} SOURCES)
      list(APPEND sources ${unit_sources})
    endforeach()
    set(exe test_${group}_units)
    catkin_add_gtest(${exe} ${sources})
    target_link_libraries(${exe} ${GTEST_MAIN_LIBRARIES})
    # A fixture in a unit's anonymous namespace is a base of its TEST classes: in a unity batch the
    # unit is an included file, which GCC flags (-Wsubobject-linkage) though nothing leaks.
    target_compile_options(${exe} PRIVATE ${AMIGOBOT_TEST_OPTIONS} -Wno-subobject-linkage)
    target_include_directories(${exe} PRIVATE ${PROJECT_SOURCE_DIR}/test/support)
    amigobot_unity_build(${exe})
    foreach(unit ${units})
      get_target_property(links ${unit} LINK_LIBRARIES)
      if(links)
        target_link_libraries(${exe} ${links})
      endif()
      get_target_property(definitions ${unit} COMPILE_DEFINITIONS)
      if(definitions)
        target_compile_definitions(${exe} PRIVATE ${definitions})
      endif()
      get_target_property(dependencies ${unit} MANUALLY_ADDED_DEPENDENCIES)
      if(dependencies)
        add_dependencies(${exe} ${dependencies})
      endif()
    endforeach()
  endforeach()
endfunction()

# A command run as one JUnit test case (scripts/test/junit_check.py writes the XML the
# counter reads). catkin's runner takes the command as one string.
function(amigobot_add_check name)
  string(REPLACE ";" " " command "${ARGN}")
  catkin_run_tests_target("check" ${name} "check-${name}.xml"
    COMMAND "${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/test/junit_check.py --name ${name} --xml ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/check-${name}.xml -- ${command}")
endfunction()

# A Google Benchmark binary (`make bench`): figures are printed, never asserted.
# amigobot_add_benchmark(NAME SOURCE LIBRARY...)
function(amigobot_add_benchmark name source)
  if(benchmark_FOUND)
    add_executable(${name} EXCLUDE_FROM_ALL ${source})
    target_link_libraries(${name} ${ARGN} benchmark::benchmark)
    target_compile_options(${name} PRIVATE ${AMIGOBOT_WARNINGS})
    set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})
  endif()
endfunction()

# pluginlib and class_loader on Debian are the ROS 2 packages, whose headers live one folder
# deeper (/usr/include/pluginlib/pluginlib/...); on a ROS 1 distro (Noetic) they do not.
set(AMIGOBOT_PLUGINLIB_WORKAROUND "")
foreach(dir /usr/include/pluginlib /usr/include/class_loader)
  get_filename_component(leaf ${dir} NAME)
  if(EXISTS ${dir}/${leaf})
    list(APPEND AMIGOBOT_PLUGINLIB_WORKAROUND ${dir})
  endif()
endforeach()
include_directories(SYSTEM ${AMIGOBOT_PLUGINLIB_WORKAROUND})
