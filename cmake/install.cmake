# The install space: `catkin_make install` gives a package that roslaunch and rosrun use with
# only the install prefix's setup.bash sourced (checked by test/install/check_install_space.sh).
# Libraries and executables are installed where they are defined (cmake/helpers.cmake).
install(DIRECTORY include/${PROJECT_NAME}/ DESTINATION ${CATKIN_PACKAGE_INCLUDE_DESTINATION})
install(DIRECTORY launch config urdf DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
install(FILES nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

# ROS scripts: rosrun and roslaunch's $(find amigobot_tracking)/scripts/... find them in the
# package's bin folder.
catkin_install_python(PROGRAMS scripts/nodes/scripted_teleop.py scripts/nodes/urdf_with_laser.py
                      DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
# Offline tools' helpers (plotting and reports), usable from the install space.
install(PROGRAMS scripts/reports/plot_run.py DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/scripts)
