# Layer 1, core: the controller that runs on the robot (the paper's maths). Eigen only.
amigobot_add_library(amigobot_tracking_core
  src/core/robot/diamond.cpp
  src/core/law/estimator.cpp
  src/core/robot/offset_point.cpp
  src/core/law/avoidance.cpp
  src/core/law/disk_clusters.cpp
  src/core/law/band_implicit.cpp
  src/core/law/prescribed_performance.cpp
  src/core/law/controller.cpp
  src/core/law/performance_envelope.cpp
  src/core/law/bounded_law.cpp
  src/core/law/paper_controller.cpp
  src/core/law/recommended_controller.cpp
  src/core/law/proportional_controller.cpp
  src/core/law/law_registry.cpp
  src/core/law/navigation_field.cpp
  src/core/law/safety_filter.cpp
  src/core/law/recommended_law.cpp
  src/core/law/yield_rollout.cpp
  src/core/law/controller_config.cpp
  src/core/support/field_table.cpp
  src/core/robot/robot_description.cpp
  src/core/support/input_file.cpp
  src/core/support/error_text.cpp
  src/core/robot/unicycle.cpp
  src/core/reference/reference.cpp
  src/core/perception/obstacle_tracker.cpp
  src/core/perception/scan_obstacles.cpp
  src/core/supervision/scan_intake.cpp
  src/core/perception/scan_health.cpp
  src/core/perception/virtual_obstacles.cpp
  src/core/supervision/resume_ramp.cpp
  src/core/supervision/tracking_supervisor.cpp
  src/core/supervision/input_age.cpp
  src/core/supervision/command_lock.cpp
  src/core/perception/body_intrusion.cpp
  src/core/supervision/tracking_loop.cpp
  src/core/reference/waypoint_reference.cpp
  src/core/reference/reference_spec.cpp
  src/core/supervision/transform_check.cpp
  src/core/supervision/clock_offset.cpp
  src/core/supervision/transform_intake.cpp
  src/core/perception/obstacle_motion.cpp
  src/core/robot/actuator_model.cpp
)
target_include_directories(amigobot_tracking_core PUBLIC include)
target_link_libraries(amigobot_tracking_core PUBLIC Eigen3::Eigen)

if(CATKIN_ENABLE_TESTING)
  foreach(unit field_table diamond resume_ramp tracking_supervisor estimator offset_point avoidance disk_clusters band_implicit controller_config controller_guards
          obstacle_tracker scan_obstacles virtual_obstacles waypoint_reference reference_spec input_age command_lock body_intrusion safety_filter tracking_loop
          rho_noise_headroom transform_intake scan_health obstacle_motion actuator_model law_registry
          obstacle_paths yield_rollout scan_intake)
    amigobot_add_unit_test(test_${unit} test/unit/test_${unit}.cpp)
    target_link_libraries(test_${unit} amigobot_tracking_core)
  endforeach()
endif()

amigobot_add_benchmark(bench_scan_obstacles test/bench/bench_scan_obstacles.cpp amigobot_tracking_core)
