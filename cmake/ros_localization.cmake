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
  # Its rostests (localization_*.test): cmake/rostests.cmake.
endif()
