// Odometry from consecutive SIPs: wrap-safe deltas of the firmware's 15-bit position and
// its angle counter, integrated along the exact arc in SI units in our own odom frame
// (which a reset re-bases without touching the robot).
#pragma once

#include "amigobot_tracking/aria/robot_params.h"
#include "amigobot_tracking/aria/sip.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace aria {

// Wrap-safe difference of two 15-bit position counters (ARIA: |d| > 0x1000 means a wrap).
int positionDelta(std::uint16_t now, std::uint16_t last);
// Difference of two angle counters, wrapped to (-units/2, units/2].
int angleDelta(int now, int last, int units_per_turn);

struct OdometryState {
  core::Pose2 pose;    // [m, m, rad] in the odom frame
  core::Twist2 twist;  // [m/s, rad/s] measured by the robot (from the SIP's wheel speeds)
};

class SipOdometry {
 public:
  explicit SipOdometry(const RobotParams& params) : params_(params) {}

  // Integrates one SIP. The first SIP after construction or reset() only sets the reference.
  const OdometryState& update(const Sip& sip);
  // Sets the pose to `pose` (origin by default); later SIP deltas move from there.
  void reset(const core::Pose2& pose = {}) { state_.pose = pose; }
  // Forgets the last SIP (new connection: the robot's counters restarted). The pose stays.
  void relink() { have_last_ = false; }
  const OdometryState& state() const { return state_; }

 private:
  RobotParams params_;
  OdometryState state_;
  bool have_last_ = false;
  Sip last_;
};

// Robot-measured twist from a SIP: v = (L+R)/2, w from ROTVEL when present, else
// (R-L)/2 * DiffConvFactor. SI units.
core::Twist2 sipTwist(const Sip& sip, const RobotParams& params);
// A sonar reading in metres (raw range * RangeConvFactor).
inline double sonarRange(const SonarReading& reading, const RobotParams& params) {
  return reading.range * params.range_conv_factor * 1e-3;
}

}  // namespace aria
}  // namespace amigobot_tracking
