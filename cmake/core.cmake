# Layer 1: the paper's maths. Eigen only: no ROS, no MRPT.
add_library(amigobot_tracking_core
  src/core/diamond.cpp
  src/core/estimator.cpp
  src/core/offset_point.cpp
  src/core/avoidance.cpp
  src/core/band_implicit.cpp
  src/core/performance.cpp
  src/core/controller.cpp
  src/core/controller_config.cpp
  src/core/field_table.cpp
  src/core/unicycle.cpp
  src/core/reference.cpp
  src/core/closed_loop.cpp
  src/core/obstacle_tracker.cpp
  src/core/raycast.cpp
  src/core/metrics.cpp
  src/core/step_size.cpp
  src/core/target_sensor.cpp
  src/core/baseline_controller.cpp
  src/core/baseline_estimators.cpp
  src/core/scan_obstacles.cpp
  src/core/virtual_obstacles.cpp
  src/core/resume_ramp.cpp
  src/core/waypoint_reference.cpp
)
target_include_directories(amigobot_tracking_core PUBLIC include)
target_link_libraries(amigobot_tracking_core PUBLIC Eigen3::Eigen)
target_compile_options(amigobot_tracking_core PRIVATE ${AMIGOBOT_WARNINGS})
