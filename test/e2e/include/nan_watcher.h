// "Nothing is published as NaN, ever", checked over every e2e and rostest run: watches every
// topic of the run whose type it knows (tf, Twist, Odometry, poses, LaserScan, Range,
// MarkerArray, Path, TrackingState, DiagnosticArray; finite_messages.h says what each may
// carry: +-inf scan ranges per REP 117, +inf ages and clearances, nothing NaN), found on the
// master as they appear, and fails the running test case when a message broke the rule
// (runAllTestsWatchingNaN() installs it around RUN_ALL_TESTS). The test node's own messages
// (a bad input it injects on purpose) and /initialpose (an input) are not judged.
#pragma once

#include <gtest/gtest.h>

#include <ros/ros.h>

#include <atomic>
#include <cstdio>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "finite_messages.h"

namespace e2e {

class NanWatcher : public ::testing::EmptyTestEventListener {
 public:
  NanWatcher() : thread_([this] { discover(); }) {}
  ~NanWatcher() override {
    stop_ = true;
    thread_.join();
  }
  NanWatcher(const NanWatcher&) = delete;
  NanWatcher& operator=(const NanWatcher&) = delete;

  void OnTestStart(const ::testing::TestInfo&) override {
    std::lock_guard<std::mutex> lock(mutex_);
    bad_.clear();
  }
  // Runs while the case is still the current one: the failure is the case's.
  void OnTestEnd(const ::testing::TestInfo&) override {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [topic, first] : bad_) ADD_FAILURE() << topic << " published a non-finite value where none is allowed (finite_messages.h): " << first;
  }
  std::size_t watched() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return subscribers_.size();
  }
  std::size_t messages() const { return messages_; }

 private:
  void report(const std::string& topic, const std::string& publisher, const std::string& what) {
    if (publisher == ros::this_node::getName()) return;  // the test's own injected input
    std::lock_guard<std::mutex> lock(mutex_);
    bad_.emplace(topic, what + " from " + publisher);  // the first one per topic
  }

  template <class M>
  void watch(const std::string& topic) {
    boost::function<void(const ros::MessageEvent<const M>&)> cb = [this, topic](const ros::MessageEvent<const M>& e) {
      ++messages_;
      const std::string what = finite::judge(*e.getConstMessage());
      if (!what.empty()) report(topic, e.getPublisherName(), what);
    };
    subscribers_.push_back(nh_.subscribe<M>(topic, 50, cb));
  }

  void subscribe(const std::string& topic, const std::string& type) {
    if (topic.size() >= 11 && topic.compare(topic.size() - 11, 11, "initialpose") == 0) return;  // an input
    if (type == "tf2_msgs/TFMessage") watch<tf2_msgs::TFMessage>(topic);
    else if (type == "geometry_msgs/Twist") watch<geometry_msgs::Twist>(topic);
    else if (type == "nav_msgs/Odometry") watch<nav_msgs::Odometry>(topic);
    else if (type == "geometry_msgs/PoseWithCovarianceStamped") watch<geometry_msgs::PoseWithCovarianceStamped>(topic);
    else if (type == "geometry_msgs/PoseStamped") watch<geometry_msgs::PoseStamped>(topic);
    else if (type == "sensor_msgs/LaserScan") watch<sensor_msgs::LaserScan>(topic);
    else if (type == "sensor_msgs/Range") watch<sensor_msgs::Range>(topic);
    else if (type == "visualization_msgs/MarkerArray") watch<visualization_msgs::MarkerArray>(topic);
    else if (type == "nav_msgs/Path") watch<nav_msgs::Path>(topic);
    else if (type == "amigobot_tracking/TrackingState") watch<amigobot_tracking::TrackingState>(topic);
    else if (type == "diagnostic_msgs/DiagnosticArray") watch<diagnostic_msgs::DiagnosticArray>(topic);
  }

  // Topics appear as the launch starts its nodes: look again every 0.5 s.
  void discover() {
    while (!stop_ && ros::ok()) {
      ros::master::V_TopicInfo topics;
      if (ros::master::getTopics(topics)) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& t : topics) {
          if (seen_.insert(t.name).second) subscribe(t.name, t.datatype);
        }
      }
      for (int i = 0; i < 5 && !stop_; ++i) ros::WallDuration(0.1).sleep();
    }
  }

  ros::NodeHandle nh_;
  mutable std::mutex mutex_;
  std::set<std::string> seen_;
  std::vector<ros::Subscriber> subscribers_;
  std::map<std::string, std::string> bad_;  // topic -> the first bad message
  std::atomic<std::size_t> messages_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// RUN_ALL_TESTS() with a NanWatcher judging every case; prints what it watched (ros::init and
// a spinner running first).
inline int runAllTestsWatchingNaN() {
  auto* watcher = new NanWatcher;
  testing::UnitTest::GetInstance()->listeners().Append(watcher);
  const int result = RUN_ALL_TESTS();
  testing::UnitTest::GetInstance()->listeners().Release(watcher);
  std::printf("NaN watcher: %zu topics watched, %zu messages checked\n", watcher->watched(), watcher->messages());
  delete watcher;  // before ROS goes down (its thread asks the master)
  return result;
}

// The main of a gtest executable that several .test files share, each choosing its cases with
// --gtest_filter (test_rostest, test_e2e): gtest's flags out of argv, then ROS as NODE (rostest
// renames it after the .test's test-name), a node handle held for the whole run, a 2-thread
// spinner for the cases' subscriptions and timers, and runAllTestsWatchingNaN(). Fails a run
// whose filter selects no case (a renamed suite must not pass silently). --gtest_list_tests
// needs no master (scripts/test/check_gtest_filters.py lists the cases). ROS is still up on
// return, for the caller's own clean-up.
inline int runSharedRosTests(int argc, char** argv, const char* node) {
  testing::InitGoogleTest(&argc, argv);
  if (testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
  ros::init(argc, argv, node);
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  int result = runAllTestsWatchingNaN();
  if (testing::UnitTest::GetInstance()->test_to_run_count() == 0) result = 1;
  spinner.stop();
  return result;
}

}  // namespace e2e
