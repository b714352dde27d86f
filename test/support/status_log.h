// The tracking nodelet's `status` over a run (/tracking/state), kept as its changes, so that an
// end-to-end test whose robot stopped or strayed can say why: "scan stale", "pose stale",
// "body intrusion ..." or "tracking" (test_bad_virtual_obstacles.cpp, test_link_loss.cpp);
// and the most obstacles the controller considered, to tell a stop for an obstacle from a stop
// for an input that went stale under load.
#pragma once

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "amigobot_tracking/TrackingState.h"

namespace e2e {

class StatusLog {
 public:
  StatusLog(ros::NodeHandle& nh, const std::string& state_topic) {
    sub_ = nh.subscribe<amigobot_tracking::TrackingState>(state_topic, 100, [this](const amigobot_tracking::TrackingState::ConstPtr& s) {
      std::lock_guard<std::mutex> lock(mutex_);
      const std::string status = s->valid ? s->status : s->status + " (not valid)";
      const double t = s->header.stamp.toSec();
      if (changes_.empty() || changes_.back().status != status) changes_.push_back({t, status, s->min_clearance_body});
      obstacles_.push_back({t, s->obstacles});
    });
  }

  // The changes after ROS time `since` (and the status in force then), one per line:
  // "+1.25 s scan stale (body clearance 2.31 m)".
  std::string since(double since) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::string out;
    for (std::size_t i = 0; i < changes_.size(); ++i) {
      if (!reaches(i, since)) continue;
      char line[320];
      std::snprintf(line, sizeof line, "\n  %+.2f s %s (body clearance %.2f m)", changes_[i].t - since,
                    changes_[i].status.c_str(), changes_[i].body_clearance);
      out += line;
    }
    return out.empty() ? " (no /tracking/state since)" : out;
  }

  // Whether every status in force after ROS time `since` was "tracking".
  bool trackedThroughout(double since) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < changes_.size(); ++i) {
      if (reaches(i, since) && changes_[i].status != "tracking") return false;
    }
    return true;
  }

  // Whether a status in force after ROS time `since` contains `text`.
  bool mentioned(double since, const std::string& text) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < changes_.size(); ++i) {
      if (reaches(i, since) && changes_[i].status.find(text) != std::string::npos) return true;
    }
    return false;
  }

  // The most obstacles (laser + virtual) the controller considered in a state after `since`.
  int mostObstacles(double since) const {
    std::lock_guard<std::mutex> lock(mutex_);
    int most = 0;
    for (const auto& [t, count] : obstacles_) {
      if (t > since) most = std::max(most, count);
    }
    return most;
  }

 private:
  struct Change {
    double t;  // [s] ROS time of the first state with this status
    std::string status;
    double body_clearance;  // [m] then
  };
  // Change i is in force at some time after `since`.
  bool reaches(std::size_t i, double since) const { return i + 1 == changes_.size() || changes_[i + 1].t > since; }

  mutable std::mutex mutex_;
  std::vector<Change> changes_;
  std::vector<std::pair<double, int>> obstacles_;  // (ROS time, obstacles) of every state
  ros::Subscriber sub_;
};

}  // namespace e2e
