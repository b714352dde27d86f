// Values the end-to-end tests judge against, shared by their cases (test_e2e.cpp,
// test_two_robots.cpp): the paper's experiment gains (config/controller_experiment.yaml,
// Section 5.3), the robot's, and the tolerances their comments justify.
#pragma once

#include <algorithm>
#include <cmath>

#include "amigobot_tracking/core/robot/actuator_limits.h"

namespace e2e {

constexpr double kRhoInf = 0.1;        // [m] steady-state bound of |e|
constexpr double kVMax = 0.3;          // [m/s] diamond half-width in v
constexpr double kWMax = 0.8;          // [rad/s] diamond half-width in omega
constexpr double kSipPeriod = 0.1;     // [s] AmigoBot SIP cycle
constexpr double kCmdVelTimeout = 0.6; // [s] driver's cmd_vel_timeout (robot.launch)
// [m] offset r of the controlled point: the shipped URDF's control_point link (read by the
// tracking node through urdf_with_laser.py's robot_description), equal to tracking.yaml's fallback.
constexpr double kOffset = 0.3;

// How far the controller's view of p_r may be from the truth: its robot pose is the driver's
// odometry (one SIP, 0.1 s, old at most) corrected by ground_truth_localization's map -> odom
// (20 Hz, 0.05 s), during which p_r moves at most max(v_max, r w_max) = 0.3 m/s: 0.045 m; the
// judge's own skew (state callback vs status query, tf's latest target) adds < 0.005 m.
constexpr double kPoseLagTolerance = 0.05;  // [m]

// [s] from a zero setpoint reaching the emulated robot to its standstill: the firmware counts
// it latency .. latency + cycle after its arrival (core/robot/actuator_model.h), then brakes from
// (v, w) at its decelerations (config/robots/amigo.yaml).
inline double firmwareStopTime(double v, double w) {
  const amigobot_tracking::core::ActuatorLimits amigo;
  return amigo.latency + amigo.cycle + std::max(std::abs(v) / amigo.trans_decel, std::abs(w) / amigo.rot_decel);
}

}  // namespace e2e
