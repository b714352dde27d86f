# Layer 3, ros: the localisation nodelet amigobot_tracking/Localization and the node
# localization_node over the localization library.
amigobot_add_library(amigobot_tracking_ros_localization
  src/ros/localization_messages.cpp
  src/ros/localization_map_io.cpp
  src/ros/localization_node.cpp
  src/ros/localization_nodelet.cpp
)
target_link_libraries(amigobot_tracking_ros_localization amigobot_tracking_localization amigobot_tracking_ros_params ${catkin_LIBRARIES})
add_dependencies(amigobot_tracking_ros_localization ${PROJECT_NAME}_generate_messages_cpp)  # LocalizationStatus

amigobot_add_tool(localization_node src/ros/programs/localization_node.cpp)
target_link_libraries(localization_node amigobot_tracking_ros_localization)

if(CATKIN_ENABLE_TESTING)
  amigobot_add_unit_test(test_stamp_gate test/unit/test_stamp_gate.cpp)
  target_link_libraries(test_stamp_gate ${catkin_LIBRARIES})
  # The nodelet (pluginlib lookup through package.xml) against a synthetic room: the test
  # publishes the scans and odom -> base_footprint itself.
  foreach(behaviour tracking mapping bad_param bad_scans)
    amigobot_add_rostest_gtest(test_localization_${behaviour} test/rostest/localization_${behaviour}.test
                               test/rostest/test_localization_${behaviour}.cpp)
    target_link_libraries(test_localization_${behaviour} amigobot_tracking_localization amigobot_tracking_world)
    add_dependencies(test_localization_${behaviour} amigobot_tracking_ros_localization)
  endforeach()
  # The standalone node run with a missing map, 20 times.
  target_compile_definitions(test_localization_bad_param PRIVATE AMIGOBOT_LOCALIZATION_NODE="$<TARGET_FILE:localization_node>")
  add_dependencies(test_localization_bad_param localization_node)
endif()
