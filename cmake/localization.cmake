# Layer 2, localization: mapping (ICP-SLAM) and localisation on a known map (ICP, global
# relocalisation) over MRPT, and map_server's map files. Core + world + MRPT + yaml-cpp; no ROS.
amigobot_add_library(amigobot_tracking_localization
  src/localization/localization_config.cpp
  src/localization/occupancy_map.cpp
  src/localization/range_scan.cpp
  src/localization/distance_field.cpp
  src/localization/localizer.cpp
  src/localization/mapper.cpp
  src/localization/pose_graph.cpp
  src/localization/graph_mapper.cpp
  src/localization/map_drawing.cpp
  src/localization/carmen_log.cpp
  src/localization/trajectory_error.cpp
  src/localization/log_replay.cpp
  src/localization/localization_verdict.cpp
  src/localization/engine.cpp
  src/localization/initial_pose.cpp
)
target_include_directories(amigobot_tracking_localization PUBLIC include)
target_link_libraries(amigobot_tracking_localization PUBLIC amigobot_tracking_core amigobot_tracking_world mrpt::slam mrpt::maps yaml-cpp)

if(CATKIN_ENABLE_TESTING)
  foreach(unit map_file localizer mapper pose_graph real_log verdict engine initial_pose)
    amigobot_add_unit_test(test_localization_${unit} test/unit/test_localization_${unit}.cpp)
    target_link_libraries(test_localization_${unit} amigobot_tracking_localization)
  endforeach()
  # The real building (test/data/real/intel.gfs.log) replayed in each mode.
  target_compile_definitions(test_localization_real_log PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  # Hostile files for every loader (map, world, scenario, robot parameters).
  amigobot_add_unit_test(test_input_files test/unit/test_input_files.cpp)
  target_link_libraries(test_input_files amigobot_tracking_localization amigobot_tracking_sim amigobot_tracking_aria)
endif()

# `make bench`: localisation update per scan (360 and 720 beams), mapping update per scan.
amigobot_add_benchmark(bench_localization test/bench/bench_localization.cpp amigobot_tracking_localization)
if(TARGET bench_localization)
  target_include_directories(bench_localization PRIVATE ${PROJECT_SOURCE_DIR}/test/support)
endif()

# world_map: a world file drawn into a map_server map (the e2e tests' surveyed maps).
amigobot_add_tool(world_map src/tools/world_map.cpp)
target_link_libraries(world_map amigobot_tracking_localization)

# log_replay: a CARMEN log through mapping or localisation, scored against its reference poses.
amigobot_add_tool(log_replay src/tools/log_replay.cpp)
target_link_libraries(log_replay amigobot_tracking_localization)
