// Lines on /rosout at or above a level, for the e2e tests that assert a node said why it
// refused something (the nodelets log through their manager; rostest starts no rosout
// aggregator, so the test listens to every node's /rosout publisher itself). Header-only on
// roscpp: the rostests of test/rostest use it too.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>


namespace e2e {

class RosoutLog {
 public:
  RosoutLog(ros::NodeHandle& nh, std::uint8_t min_level) : min_level_(min_level) {
    sub_ = nh.subscribe("/rosout", 1000, &RosoutLog::onLog, this);
  }
  // n publishers (this node, the manager, ...) are connected, so no line of theirs can be
  // missed any more.
  bool connected(std::uint32_t publishers, double timeout) {
    return poll([&] { return sub_.getNumPublishers() >= publishers; }, timeout);
  }
  // Lines so far: pass it as `since` to look only at what comes after.
  std::size_t count() {
    std::lock_guard<std::mutex> lock(mutex_);
    return lines_.size();
  }
  // Waits for a line containing every one of `texts`, among the lines from index `since`;
  // *found = that line.
  bool waitForMentionOfAll(const std::vector<std::string>& texts, double timeout, std::size_t since = 0,
                           std::string* found = nullptr) {
    return poll([&] {
      std::lock_guard<std::mutex> lock(mutex_);
      for (std::size_t i = since; i < lines_.size(); ++i) {
        bool all = true;
        for (const auto& t : texts) all = all && lines_[i].find(t) != std::string::npos;
        if (!all) continue;
        if (found) *found = lines_[i];
        return true;
      }
      return false;
    }, timeout);
  }
  bool waitForMention(const std::string& text, double timeout, std::size_t since = 0) {
    return waitForMentionOfAll({text}, timeout, since);
  }

 private:
  static bool poll(const std::function<bool()>& predicate, double timeout) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
    while (std::chrono::steady_clock::now() < end) {
      if (predicate()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return predicate();
  }
  void onLog(const rosgraph_msgs::Log::ConstPtr& log) {
    if (log->level < min_level_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    lines_.push_back(log->msg);
  }
  const std::uint8_t min_level_;
  ros::Subscriber sub_;
  std::mutex mutex_;
  std::vector<std::string> lines_;
};

}  // namespace e2e
