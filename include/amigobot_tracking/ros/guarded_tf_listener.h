// A tf listener that judges every sample before it enters the tf2 buffer (the pure
// judgement is core::TransformIntake): a NaN/inf or non-unit-quaternion transform is refused,
// a dynamic one stamped further ahead of its arrival than `future_tolerance` is dropped
// (tf2 would keep it as the frame's "latest" and hide the good samples after it), each with
// a WARN naming the frames and why (throttled per frame). It also estimates each publisher's
// clock offset from its stamps and arrivals, so a reader can tell skewed clocks from a dead
// publisher. Subscribes /tf and /tf_static like tf2_ros::TransformListener, on its own
// callback queue and thread (the buffer must not wait for a busy node).
#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

#include "amigobot_tracking/core/supervision/transform_intake.h"
#include "amigobot_tracking/ros/refusal_log.h"

namespace amigobot_tracking {
namespace ros_layer {

class GuardedTfListener {
 public:
  GuardedTfListener(tf2_ros::Buffer& buffer, const ros::NodeHandle& nh, double future_tolerance);
  ~GuardedTfListener();
  GuardedTfListener(const GuardedTfListener&) = delete;
  GuardedTfListener& operator=(const GuardedTfListener&) = delete;

  // The clock of the publishers of `frames` (child frames) at `now`: the named one with the
  // largest offset, else the first known; unknown when none sent samples lately.
  core::FrameClock clockOf(const std::vector<std::string>& frames, const ros::Time& now) const;
  // The frames of the buffer's chain from `frame` to `fixed` at the latest time (tf2's own chain).
  std::vector<std::string> chain(const std::string& fixed, const std::string& frame) const;

 private:
  void onTf(const ros::MessageEvent<const tf2_msgs::TFMessage>& event, bool is_static);

  tf2_ros::Buffer& buffer_;
  ros::NodeHandle nh_;  // on queue_
  ros::CallbackQueue queue_;
  ros::Subscriber tf_sub_, static_sub_;
  mutable std::mutex mutex_;  // intake_, refusals_
  core::TransformIntake intake_;
  std::map<std::string, RefusalLog> refusals_;  // by child frame
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
