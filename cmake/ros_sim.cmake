# Layer 3, ros: nodes that stand in for the lab's sensors and localisation on the emulated
# robot: sim_laser (ray-cast world) and ground_truth_localization (map -> odom);
# trail_publisher (rviz trails of the robot and the target) is used on the real robot too;
# world_markers draws the world file in rviz.
amigobot_add_library(amigobot_tracking_ros_sim
  src/ros/sim_laser.cpp
  src/ros/ground_truth.cpp
  src/ros/trail.cpp
  src/ros/world_markers.cpp
)
target_link_libraries(amigobot_tracking_ros_sim amigobot_tracking_ros amigobot_tracking_ros_params amigobot_tracking_aria amigobot_tracking_world ${catkin_LIBRARIES})

amigobot_add_tool(sim_laser src/ros/programs/sim_laser_node.cpp)
target_link_libraries(sim_laser amigobot_tracking_ros_sim amigobot_tracking_world)
amigobot_add_tool(trail_publisher src/ros/programs/trail_publisher_node.cpp)
target_link_libraries(trail_publisher amigobot_tracking_ros_sim)
amigobot_add_tool(world_markers src/ros/programs/world_markers_node.cpp)
target_link_libraries(world_markers amigobot_tracking_ros_sim amigobot_tracking_world)
amigobot_add_tool(ground_truth_localization src/ros/programs/ground_truth_localization_node.cpp)
target_link_libraries(ground_truth_localization amigobot_tracking_ros_sim)

if(CATKIN_ENABLE_TESTING)
  foreach(unit trail sim_laser world_markers)
    amigobot_add_unit_test(test_${unit} test/unit/test_${unit}.cpp)
    target_link_libraries(test_${unit} amigobot_tracking_ros_sim)
  endforeach()
  # The status client against the real emulator executable (free ports, killed on exit).
  amigobot_add_unit_test(test_ground_truth test/unit/test_ground_truth.cpp)
  target_link_libraries(test_ground_truth amigobot_tracking_ros_sim)
  target_compile_definitions(test_ground_truth PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
  add_dependencies(test_ground_truth amigobot_emulator)
endif()
