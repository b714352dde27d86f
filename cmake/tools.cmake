# Thin command-line mains over the libraries; `rosrun amigobot_tracking <tool>` finds them.
function(amigobot_add_tool name)
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} CLI11::CLI11)
  target_compile_options(${name} PRIVATE ${AMIGOBOT_WARNINGS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})
  install(TARGETS ${name} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endfunction()

amigobot_add_tool(amigobot_sim src/tools/amigobot_sim.cpp)
target_link_libraries(amigobot_sim amigobot_tracking_sim)
target_compile_definitions(amigobot_sim PRIVATE AMIGOBOT_PLOT_SCRIPT="${PROJECT_SOURCE_DIR}/scripts/plot_run.py")

# ROS tool scripts: `rosrun amigobot_tracking scripted_teleop.py` (roslaunch finds them in scripts/).
catkin_install_python(PROGRAMS scripts/scripted_teleop.py DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
