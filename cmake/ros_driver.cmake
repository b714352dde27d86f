# Layer 3 (driver part): the AmigoBot driver nodelet amigobot_tracking/Driver and the node
# amigobot_driver_node over the aria library.
# pluginlib/class_loader on Debian are the ROS 2 headers: add their folders explicitly.
include_directories(SYSTEM /usr/include/pluginlib /usr/include/class_loader)

add_library(amigobot_tracking_ros_driver
  src/ros/driver.cpp
  src/ros/driver_nodelet.cpp
)
target_link_libraries(amigobot_tracking_ros_driver amigobot_tracking_aria amigobot_tracking_ros_params ${catkin_LIBRARIES})
target_compile_options(amigobot_tracking_ros_driver PRIVATE ${AMIGOBOT_WARNINGS})
install(TARGETS amigobot_tracking_ros_driver LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

amigobot_add_tool(amigobot_driver_node src/ros/driver_node.cpp)
target_link_libraries(amigobot_driver_node amigobot_tracking_ros_driver)

if(CATKIN_ENABLE_TESTING)
  find_package(rostest REQUIRED)
  # The driver loaded as a nodelet (pluginlib lookup through package.xml) against the
  # emulator executable on a free port.
  add_rostest_gtest(test_driver_ros test/rostest/driver.test test/rostest/test_driver_ros.cpp)
  target_link_libraries(test_driver_ros amigobot_tracking_aria ${catkin_LIBRARIES} ${GTEST_LIBRARIES})
  target_include_directories(test_driver_ros PRIVATE test/aria)
  target_compile_options(test_driver_ros PRIVATE ${AMIGOBOT_WARNINGS})
  target_compile_definitions(test_driver_ros PRIVATE AMIGOBOT_EMULATOR="$<TARGET_FILE:amigobot_emulator>")
  add_dependencies(test_driver_ros amigobot_emulator amigobot_tracking_ros_driver)
  add_dependencies(tests test_driver_ros)
endif()
