#include "amigobot_tracking/ros/guarded_tf_listener.h"

#include <cmath>

#include <tf2/exceptions.h>

namespace amigobot_tracking {
namespace ros_layer {

GuardedTfListener::GuardedTfListener(tf2_ros::Buffer& buffer, const ros::NodeHandle& nh, double future_tolerance)
    : buffer_(buffer), nh_(nh), intake_(future_tolerance) {
  // Its own thread fills the buffer, as tf2_ros::TransformListener's: lookups with a timeout
  // may wait (without this, tf2 refuses them with "Do not call canTransform ... with a timeout").
  buffer_.setUsingDedicatedThread(true);
  nh_.setCallbackQueue(&queue_);
  // The same topics, queue sizes and transport hint as tf2_ros::TransformListener.
  tf_sub_ = nh_.subscribe<tf2_msgs::TFMessage>(
      "/tf", 100, [this](const ros::MessageEvent<const tf2_msgs::TFMessage>& e) { onTf(e, false); },
      ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  static_sub_ = nh_.subscribe<tf2_msgs::TFMessage>(
      "/tf_static", 100, [this](const ros::MessageEvent<const tf2_msgs::TFMessage>& e) { onTf(e, true); },
      ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  thread_ = std::thread([this] {
    while (!stop_ && nh_.ok()) queue_.callAvailable(ros::WallDuration(0.01));
  });
}

GuardedTfListener::~GuardedTfListener() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  tf_sub_.shutdown();
  static_sub_.shutdown();
}

void GuardedTfListener::onTf(const ros::MessageEvent<const tf2_msgs::TFMessage>& event, bool is_static) {
  const double arrival = ros::Time::now().toSec();
  const std::string authority = event.getPublisherName();
  for (const geometry_msgs::TransformStamped& t : event.getConstMessage()->transforms) {
    const auto& p = t.transform.translation;
    const auto& q = t.transform.rotation;
    core::IntakeVerdict verdict;
    bool log = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      verdict = intake_.judge(t.child_frame_id, t.header.stamp.toSec(), arrival, {p.x, p.y, p.z}, {q.x, q.y, q.z, q.w},
                              is_static);
      RefusalLog& refusal = refusals_[t.child_frame_id];
      if (verdict.accept) {
        refusal.clear();
      } else {
        // Throttled by kind, not by the number in it: a steady offset must not log every sample.
        const bool ahead = verdict.problem.rfind("stamped ", 0) == 0;
        log = refusal.due(ahead ? "stamped ahead" : verdict.problem);
      }
    }
    if (!verdict.accept) {
      if (log) {
        ROS_WARN_STREAM_NAMED("tf_guard", "tf " << t.header.frame_id << " -> " << t.child_frame_id << " from "
                                                << authority << (is_static ? " (static)" : "")
                                                << " dropped: " << verdict.problem);
      }
      continue;
    }
    try {
      buffer_.setTransform(t, authority, is_static);
    } catch (const tf2::TransformException& e) {
      ROS_WARN_STREAM_THROTTLE_NAMED(5.0, "tf_guard", "tf " << t.header.frame_id << " -> " << t.child_frame_id
                                                            << " refused by tf2: " << e.what());
    }
  }
}

core::FrameClock GuardedTfListener::clockOf(const std::vector<std::string>& frames, const ros::Time& now) const {
  core::FrameClock out;
  std::lock_guard<std::mutex> lock(mutex_);
  for (const std::string& frame : frames) {
    const core::FrameClock c = intake_.clock(frame, now.toSec());
    if (!c.known) continue;
    const bool worse = !c.problem.empty() && (out.problem.empty() || std::abs(c.offset) > std::abs(out.offset));
    if (!out.known || worse) out = c;
  }
  return out;
}

std::vector<std::string> GuardedTfListener::chain(const std::string& fixed, const std::string& frame) const {
  std::vector<std::string> frames;
  try {
    buffer_._chainAsVector(fixed, ros::Time(0), frame, ros::Time(0), fixed, frames);
  } catch (const tf2::TransformException&) {
    frames = {frame};
  }
  return frames;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
