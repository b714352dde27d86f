# Layer 3: ROS 1 nodelets and nodes over the core.
# pluginlib/class_loader on Debian are the ROS 2 headers: add their folders explicitly.
include_directories(SYSTEM /usr/include/pluginlib /usr/include/class_loader ${urdfdom_INCLUDE_DIRS})

# The one ROS parameter reader, shared by every ROS library and node.
add_library(amigobot_tracking_ros_params src/ros/param_reader.cpp)
target_link_libraries(amigobot_tracking_ros_params amigobot_tracking_core ${catkin_LIBRARIES})
target_compile_options(amigobot_tracking_ros_params PRIVATE ${AMIGOBOT_WARNINGS})
install(TARGETS amigobot_tracking_ros_params
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

add_library(amigobot_tracking_ros
  src/ros/conversions.cpp
  src/ros/markers.cpp
  src/ros/tracking_params.cpp
  src/ros/reconfigure_mapping.cpp
  src/ros/tracking_node.cpp
  src/ros/tracking_virtual_obstacles.cpp
  src/ros/tracking_nodelet.cpp
)
target_link_libraries(amigobot_tracking_ros amigobot_tracking_core amigobot_tracking_ros_params ${catkin_LIBRARIES} ${urdfdom_LIBRARIES})
target_compile_options(amigobot_tracking_ros PRIVATE ${AMIGOBOT_WARNINGS})
add_dependencies(amigobot_tracking_ros ${PROJECT_NAME}_generate_messages_cpp ${PROJECT_NAME}_gencfg)
install(TARGETS amigobot_tracking_ros
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

amigobot_add_tool(tracking_node src/ros/tracking_node_main.cpp)
target_link_libraries(tracking_node amigobot_tracking_ros)

amigobot_add_tool(reference_publisher src/tools/reference_publisher.cpp)
target_link_libraries(reference_publisher amigobot_tracking_ros)
