# Offline simulator: scenario files (yaml-cpp) and run outputs over the core. No ROS.
add_library(amigobot_tracking_sim
  src/sim/scenario.cpp
  src/sim/simulator.cpp
  src/sim/monte_carlo.cpp
  src/sim/json.cpp
)
target_include_directories(amigobot_tracking_sim PUBLIC include)
target_link_libraries(amigobot_tracking_sim PUBLIC amigobot_tracking_core ${YAML_CPP_LIBRARIES} nlohmann_json::nlohmann_json)
target_compile_options(amigobot_tracking_sim PRIVATE ${AMIGOBOT_WARNINGS})
