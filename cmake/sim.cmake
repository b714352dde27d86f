# Layer 2, sim: the offline-simulation model over the core (closed loop, integrators, sensor
# models, metrics, baselines, scenario files, Monte Carlo). Core + yaml-cpp + nlohmann-json; no ROS, no MRPT.
amigobot_add_library(amigobot_tracking_sim
  src/sim/closed_loop.cpp
  src/sim/step_size.cpp
  src/sim/target_sensor.cpp
  src/sim/metrics.cpp
  src/sim/baseline_estimators.cpp
  src/sim/scenario.cpp
  src/sim/scenario_check.cpp
  src/sim/scenario_fields.cpp
  src/sim/scenario_names.cpp
  src/sim/simulator.cpp
  src/sim/monte_carlo.cpp
  src/sim/gain_tuner.cpp
  src/sim/json.cpp
  src/sim/tracking_verdict.cpp
  src/sim/robot_description.cpp
  src/sim/actuator_fit.cpp
)
target_include_directories(amigobot_tracking_sim PUBLIC include)
target_link_libraries(amigobot_tracking_sim PUBLIC amigobot_tracking_core ${YAML_CPP_LIBRARIES} nlohmann_json::nlohmann_json)

# amigobot_sim is built in sim_mrpt.cmake (it also runs the MRPT peer).

if(CATKIN_ENABLE_TESTING)
  foreach(unit closed_loop metrics tracking_verdict baselines controller_extensions)
    amigobot_add_unit_test(test_${unit} test/unit/test_${unit}.cpp)
    target_link_libraries(test_${unit} amigobot_tracking_sim)
  endforeach()
  # Scenario files and whole simulated runs read the shipped config/scenarios.
  foreach(unit sim_scenario sim_closed_loop sim_extensions recommended_law field_lookahead command_rate_box gain_tuner sim_dynamics yield_to_people)
    amigobot_add_unit_test(test_${unit} test/unit/test_${unit}.cpp)
    target_link_libraries(test_${unit} amigobot_tracking_sim)
    target_compile_definitions(test_${unit} PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  endforeach()
endif()

amigobot_add_benchmark(bench_core test/bench/bench_core.cpp amigobot_tracking_sim)
