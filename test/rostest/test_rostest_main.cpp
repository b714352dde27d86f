// The one main of test_rostest, the executable of every gtest rostest under test/rostest/
// (cmake/rostests.cmake); each .test file picks its cases with --gtest_filter. Every run is the
// same process: ROS up (rostest names the node after the .test's test-name), a 2-thread spinner
// for the cases' own subscriptions and timers (the most any case's executable had before they
// were one), and the NaN watcher judging every case (nan_watcher.h: a non-finite value published
// by another node on a topic it knows fails the case).
#include <gtest/gtest.h>

#include <ros/ros.h>

#include "nan_watcher.h"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  // --gtest_list_tests needs no master (scripts/test/check_gtest_filters.py lists the cases).
  if (testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
  ros::init(argc, argv, "test_rostest");
  ros::NodeHandle nh;  // the node lives for the whole run, not only while a case holds a handle
  ros::AsyncSpinner spinner(2);
  spinner.start();
  int result = e2e::runAllTestsWatchingNaN();
  // A .test file whose --gtest_filter matches no case must not pass silently.
  if (testing::UnitTest::GetInstance()->test_to_run_count() == 0) result = 1;
  spinner.stop();
  return result;
}
