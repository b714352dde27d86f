// "Nothing is published as NaN, ever", checked over every e2e run: watches every topic of the
// run whose type carries a pose or a command (tf2_msgs/TFMessage, geometry_msgs/Twist,
// nav_msgs/Odometry, geometry_msgs/PoseWithCovarianceStamped, geometry_msgs/PoseStamped),
// found on the master as they appear, and fails the running test case when one carried a NaN
// or an infinity (test_e2e.cpp's main installs it for every case). The test node's own
// messages (a bad input it injects on purpose) are not judged. Not covered: laser scans
// (REP 117 allows NaN and inf ranges), the tracking node's ~state and markers.
#pragma once

#include <gtest/gtest.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

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
    for (const auto& [topic, first] : bad_) ADD_FAILURE() << topic << " published a NaN or infinity: " << first;
  }
  std::size_t watched() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return subscribers_.size();
  }

 private:
  static bool finite(const geometry_msgs::Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
  static bool finite(const geometry_msgs::Point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
  static bool finite(const geometry_msgs::Quaternion& q) {
    return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
  }
  static bool finite(const geometry_msgs::Pose& p) { return finite(p.position) && finite(p.orientation); }
  static bool finite(const geometry_msgs::Twist& t) { return finite(t.linear) && finite(t.angular); }

  void report(const std::string& topic, const std::string& publisher, const std::string& what) {
    if (publisher == ros::this_node::getName()) return;  // the test's own injected input
    std::lock_guard<std::mutex> lock(mutex_);
    bad_.emplace(topic, what + " from " + publisher);  // the first one per topic
  }

  template <class M>
  void watch(const std::string& topic, std::function<std::string(const M&)> judge) {
    boost::function<void(const ros::MessageEvent<const M>&)> cb = [this, topic, judge](const ros::MessageEvent<const M>& e) {
      const std::string what = judge(*e.getConstMessage());
      if (!what.empty()) report(topic, e.getPublisherName(), what);
    };
    subscribers_.push_back(nh_.subscribe<M>(topic, 50, cb));
  }

  void subscribe(const std::string& topic, const std::string& type) {
    if (topic.size() >= 11 && topic.compare(topic.size() - 11, 11, "initialpose") == 0) return;  // an input
    if (type == "tf2_msgs/TFMessage") {
      watch<tf2_msgs::TFMessage>(topic, [](const tf2_msgs::TFMessage& m) {
        for (const auto& t : m.transforms) {
          if (!finite(t.transform.translation) || !finite(t.transform.rotation)) {
            return t.header.frame_id + " -> " + t.child_frame_id;
          }
        }
        return std::string();
      });
    } else if (type == "geometry_msgs/Twist") {
      watch<geometry_msgs::Twist>(topic, [](const geometry_msgs::Twist& m) { return finite(m) ? "" : std::string("twist"); });
    } else if (type == "nav_msgs/Odometry") {
      watch<nav_msgs::Odometry>(topic, [](const nav_msgs::Odometry& m) {
        return finite(m.pose.pose) && finite(m.twist.twist) ? "" : std::string("odometry");
      });
    } else if (type == "geometry_msgs/PoseWithCovarianceStamped") {
      watch<geometry_msgs::PoseWithCovarianceStamped>(
          topic, [](const geometry_msgs::PoseWithCovarianceStamped& m) { return finite(m.pose.pose) ? "" : std::string("pose"); });
    } else if (type == "geometry_msgs/PoseStamped") {
      watch<geometry_msgs::PoseStamped>(topic,
                                        [](const geometry_msgs::PoseStamped& m) { return finite(m.pose) ? "" : std::string("pose"); });
    }
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
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace e2e
