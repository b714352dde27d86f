# Layer 3, ros: the AmigoBot driver nodelet amigobot_tracking/Driver and the node
# amigobot_driver_node over the aria library.
amigobot_add_library(amigobot_tracking_ros_driver
  src/ros/driver.cpp
  src/ros/driver_nodelet.cpp
  src/ros/driver_state_topics.cpp
  src/ros/driver_supervision.cpp
  src/ros/sonar_cloud.cpp
)
target_link_libraries(amigobot_tracking_ros_driver amigobot_tracking_aria amigobot_tracking_ros_params ${catkin_LIBRARIES})
add_dependencies(amigobot_tracking_ros_driver ${PROJECT_NAME}_generate_messages_cpp ${PROJECT_NAME}_gencfg)

amigobot_add_tool(amigobot_driver_node src/ros/programs/driver_node.cpp)
target_link_libraries(amigobot_driver_node amigobot_tracking_ros_driver)
# Its rostests (driver.test, driver_one_way_link.test): cmake/rostests.cmake.
