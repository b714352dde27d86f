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

if(CATKIN_ENABLE_TESTING)
  # The driver loaded as a nodelet (pluginlib lookup through package.xml) against the
  # emulator executable on a free port.
  amigobot_add_rostest_gtest(test_driver_ros test/rostest/driver.test test/rostest/test_driver_ros.cpp)
  target_link_libraries(test_driver_ros amigobot_tracking_aria)
  target_compile_definitions(test_driver_ros PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
  add_dependencies(test_driver_ros amigobot_emulator amigobot_tracking_ros_driver ${PROJECT_NAME}_generate_messages_cpp)
endif()

if(CATKIN_ENABLE_TESTING)
  # The emulator's control socket cuts the driver -> robot direction: the driver names it.
  amigobot_add_rostest_gtest(test_driver_one_way_link test/rostest/driver_one_way_link.test
                             test/rostest/test_driver_one_way_link.cpp)
  target_link_libraries(test_driver_one_way_link amigobot_tracking_aria)
  target_compile_definitions(test_driver_one_way_link PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
  add_dependencies(test_driver_one_way_link amigobot_emulator amigobot_tracking_ros_driver)
endif()
