# Offline simulator: scenario files (yaml-cpp) and run outputs over the core. No ROS.
add_library(amigobot_tracking_sim
  src/sim/scenario.cpp
  src/sim/scenario_fields.cpp
  src/sim/scenario_names.cpp
  src/sim/simulator.cpp
  src/sim/monte_carlo.cpp
)
target_include_directories(amigobot_tracking_sim PUBLIC include)
target_link_libraries(amigobot_tracking_sim PUBLIC amigobot_tracking_core ${YAML_CPP_LIBRARIES})
target_compile_options(amigobot_tracking_sim PRIVATE ${AMIGOBOT_WARNINGS})
