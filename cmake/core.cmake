# Layer 1, core: the controller that runs on the robot (the paper's maths). Eigen only.
amigobot_add_library(amigobot_tracking_core
  src/core/diamond.cpp
  src/core/estimator.cpp
  src/core/offset_point.cpp
  src/core/avoidance.cpp
  src/core/disk_clusters.cpp
  src/core/band_implicit.cpp
  src/core/prescribed_performance.cpp
  src/core/controller.cpp
  src/core/performance_envelope.cpp
  src/core/bounded_law.cpp
  src/core/paper_controller.cpp
  src/core/recommended_controller.cpp
  src/core/proportional_controller.cpp
  src/core/law_registry.cpp
  src/core/navigation_field.cpp
  src/core/safety_filter.cpp
  src/core/recommended_law.cpp
  src/core/controller_config.cpp
  src/core/field_table.cpp
  src/core/robot_description.cpp
  src/core/input_file.cpp
  src/core/error_text.cpp
  src/core/unicycle.cpp
  src/core/reference.cpp
  src/core/obstacle_tracker.cpp
  src/core/scan_obstacles.cpp
  src/core/scan_health.cpp
  src/core/virtual_obstacles.cpp
  src/core/resume_ramp.cpp
  src/core/tracking_supervisor.cpp
  src/core/input_age.cpp
  src/core/command_lock.cpp
  src/core/body_intrusion.cpp
  src/core/tracking_loop.cpp
  src/core/waypoint_reference.cpp
  src/core/transform_check.cpp
  src/core/clock_offset.cpp
  src/core/transform_intake.cpp
  src/core/obstacle_motion.cpp
  src/core/actuator_model.cpp
)
target_include_directories(amigobot_tracking_core PUBLIC include)
target_link_libraries(amigobot_tracking_core PUBLIC Eigen3::Eigen)

if(CATKIN_ENABLE_TESTING)
  foreach(unit field_table diamond resume_ramp tracking_supervisor estimator offset_point avoidance disk_clusters band_implicit controller_config controller_guards
          obstacle_tracker scan_obstacles virtual_obstacles waypoint_reference input_age command_lock body_intrusion safety_filter tracking_loop
          rho_noise_headroom transform_intake scan_health obstacle_motion actuator_model law_registry
          obstacle_paths)
    amigobot_add_unit_test(test_${unit} test/unit/test_${unit}.cpp)
    target_link_libraries(test_${unit} amigobot_tracking_core)
  endforeach()
endif()

amigobot_add_benchmark(bench_scan_obstacles test/bench/bench_scan_obstacles.cpp amigobot_tracking_core)
