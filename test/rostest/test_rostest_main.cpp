// The one main of test_rostest, the executable of every gtest rostest under test/rostest/
// (cmake/rostests.cmake); each .test file picks its cases with --gtest_filter. Every run is the
// same process (nan_watcher.h's runSharedRosTests): ROS up (rostest names the node after the
// .test's test-name), a 2-thread spinner for the cases' own subscriptions and timers (the most
// any case's executable had before they were one), and the NaN watcher judging every case (a
// non-finite value published by another node on a topic it knows fails the case).
#include "nan_watcher.h"

int main(int argc, char** argv) { return e2e::runSharedRosTests(argc, argv, "test_rostest"); }
