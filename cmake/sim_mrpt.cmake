# Layer 3, sim_mrpt: laws of the offline closed loop built on MRPT (the reactive navigator as a
# peer for Table 2). Core + world + sim + MRPT (nav); no ROS. amigobot_sim links it.
amigobot_add_library(amigobot_tracking_sim_mrpt
  src/sim_mrpt/reactive_law.cpp
  src/sim_mrpt/reactive_config.cpp
)
target_include_directories(amigobot_tracking_sim_mrpt PUBLIC include)
target_link_libraries(amigobot_tracking_sim_mrpt PUBLIC amigobot_tracking_sim amigobot_tracking_world mrpt::nav)

amigobot_add_tool(amigobot_sim src/tools/amigobot_sim.cpp)
target_link_libraries(amigobot_sim amigobot_tracking_sim amigobot_tracking_sim_mrpt)
target_compile_definitions(amigobot_sim PRIVATE AMIGOBOT_PLOT_SCRIPT="${PROJECT_SOURCE_DIR}/scripts/reports/plot_run.py")

if(CATKIN_ENABLE_TESTING)
  amigobot_add_unit_test(test_sim_mrpt_reactive test/unit/test_sim_mrpt_reactive.cpp)
  target_link_libraries(test_sim_mrpt_reactive amigobot_tracking_sim_mrpt)
  target_compile_definitions(test_sim_mrpt_reactive PRIVATE AMIGOBOT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
