// Recording of the tracking nodelet's control steps with the ground truth at each one, for the
// end-to-end tests (test_e2e.cpp, test_avoidance.cpp).
#pragma once

#include <cmath>
#include <limits>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "amigobot_tracking/TrackingState.h"
#include "experiment.h"
#include "judge.h"

namespace e2e {

struct Step {
  double t = 0.0;       // [s] since the first valid step
  double rho = 0.0;     // [m] controller's envelope
  double e_true = 0.0;  // [m] |p_d - p_r| from ground truth and the target's tf
  double e_ctrl = 0.0;  // [m] controller's own |e|
  bool widened = false;
  EmulatorStatus truth;  // the robot's true state at that step
  Eigen::Vector2d p_d = Eigen::Vector2d::Zero();  // [m] the target's position (tf) at that step
  // [m] |believed - true| position of base_link: tf map -> base_link (the localisation the
  // stack runs on, newest) against the ground truth; NaN when tf has no such pose yet.
  double loc_error = std::numeric_limits<double>::quiet_NaN();
};

// Records every valid control step of /tracking/state with the true error at that moment.
class StepRecorder {
 public:
  StepRecorder(ros::NodeHandle& nh, const std::string& state_topic, int status_port, std::string target_frame)
      : truth_(status_port), target_frame_(std::move(target_frame)), listener_(tf_) {
    sub_ = nh.subscribe(state_topic, 100, &StepRecorder::onState, this);
  }
  std::vector<Step> steps() {
    std::lock_guard<std::mutex> lock(mutex_);
    return steps_;
  }
  std::string counts() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::to_string(states_) + " states, " + std::to_string(invalid_) + " not valid, " +
           std::to_string(no_truth_) + " without ground truth, " + std::to_string(no_target_) + " without target tf";
  }

 private:
  void onState(const amigobot_tracking::TrackingState::ConstPtr& state) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++states_;
    }
    if (!state->valid) return count(&invalid_);
    EmulatorStatus s;
    if (!truth_.tryTruth(&s)) return count(&no_truth_);
    geometry_msgs::TransformStamped target;
    try {
      target = tf_.lookupTransform("map", target_frame_, ros::Time(0));
    } catch (const tf2::TransformException&) {
      return count(&no_target_);
    }
    const Eigen::Vector2d p_d(target.transform.translation.x, target.transform.translation.y);
    double loc_error = std::numeric_limits<double>::quiet_NaN();
    try {
      const auto believed = tf_.lookupTransform("map", "base_link", ros::Time(0));
      loc_error = std::hypot(believed.transform.translation.x - s.pose.x, believed.transform.translation.y - s.pose.y);
    } catch (const tf2::TransformException&) {
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (steps_.empty()) t0_ = state->header.stamp.toSec();
    Step step;
    step.t = state->header.stamp.toSec() - t0_;
    step.rho = state->rho;
    step.e_true = (p_d - e2e::offsetPoint(s, kOffset)).norm();
    step.e_ctrl = state->e_norm;
    step.widened = state->envelope_widened;
    step.truth = s;
    step.p_d = p_d;
    step.loc_error = loc_error;
    steps_.push_back(step);
  }

  e2e::GroundTruth truth_;
  std::string target_frame_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  ros::Subscriber sub_;
  std::mutex mutex_;
  std::vector<Step> steps_;
  double t0_ = 0.0;
  int states_ = 0, invalid_ = 0, no_truth_ = 0, no_target_ = 0;  // why states were not judged
  void count(int* counter) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++*counter;
  }
};

inline ::testing::AssertionResult waitForSteps(StepRecorder& recorder, double duration, double timeout) {
  double reached = 0.0;
  const bool done = e2e::waitFor([&] {
    const auto steps = recorder.steps();
    reached = steps.empty() ? 0.0 : steps.back().t;
    return !steps.empty() && steps.back().t >= duration;
  }, timeout);
  if (done) return ::testing::AssertionSuccess();
  // Which part was late: no /tracking/state at all (the tracking nodelet), states without
  // ground truth (the emulator) or without the target's tf (the reference publisher).
  return ::testing::AssertionFailure() << "valid control steps for " << reached << " s of the " << duration
                                       << " s wanted within " << timeout << " s: " << recorder.counts();
}

}  // namespace e2e
