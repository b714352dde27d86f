// Ground-truth localisation for the emulated robot: the emulator's status socket
// (aria/emulator_status.h) reports the true pose of base_link in the world (= map); the
// map -> odom correction makes map -> odom -> base_link equal that pose (REP 105), as a
// perfect localiser would.
#pragma once

#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include <ros/node_handle.h>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace ros_layer {

// map -> odom such that (map -> odom) * (odom -> base) = truth: truth * inverse(odom_base).
core::Pose2 mapToOdom(const core::Pose2& truth, const core::Pose2& odom_base);

// Pairs each true pose with the odometry of the same instant. The driver's odometry comes a
// SIP cycle (0.1 s) apart and later under load; the truth of *now* paired with the *latest*
// odometry put map -> odom off by the motion in between (v x its age: 3 cm at 0.3 m/s and 0.1 s,
// more on a loaded machine), and the tracking takes such a change for a localisation jump. Each
// true pose waits here until odometry reaches its stamp (tf interpolates odometry there).
class TruthPairing {
 public:
  // odom -> base at `stamp` [s]; false while odometry does not reach it (or not any more).
  using OdometryAt = std::function<bool(double stamp, core::Pose2* odom_base)>;

  explicit TruthPairing(double keep = 1.0) : keep_(keep) {}  // [s] true poses older are dropped
  void add(double stamp, const core::Pose2& truth);
  // map -> odom from the newest true pose that odometry reaches; it and older ones are dropped.
  // Empty when odometry reaches none yet.
  std::optional<core::Pose2> correction(const OdometryAt& odom_at);
  std::size_t pending() const { return samples_.size(); }

 private:
  double keep_;
  std::deque<std::pair<double, core::Pose2>> samples_;  // oldest first
};

struct GroundTruthConfig {
  std::string host = "127.0.0.1";       // emulator's status socket address
  int port = 8102;                      // its --status-port
  std::string global_frame = "map";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  double rate = 20.0;                   // [Hz] map -> odom updates
  double transform_tolerance = 0.1;     // [s] map -> odom is stamped this far ahead (as amcl does)
  double socket_timeout = 0.5;          // [s] a status reply slower than this counts as a lost link
  double reconnect_period = 1.0;        // [s] between reconnection attempts
  // false: only the `ground_truth` topic (for judging a run whose map -> odom comes from the
  // real localisation); true: also map -> odom, so map -> base_link is the true pose.
  bool publish_tf = true;

  std::string validate() const;  // empty when valid, else "key: reason"
};

const core::FieldTable<GroundTruthConfig>& groundTruthFields();

std::string loadGroundTruthConfig(const ros::NodeHandle& pnh, GroundTruthConfig* config);

}  // namespace ros_layer
}  // namespace amigobot_tracking
