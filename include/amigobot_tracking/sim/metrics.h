// Figures of merit of one closed-loop run, accumulated step by step.
//
// Every step contributes over the time h its command is held (zero-order hold: the state
// is sampled at t_k and the command u_k acts on [t_k, t_k + h_k)), so the averages are
// left Riemann sums of the continuous-time integrals and do not depend on whether the
// step is fixed or variable:
//   ASE = (1/T) sum h_k |e_k|^2          [m^2]   average squared tracking error
//   AAE = (1/T) sum h_k |e_k|            [m]     average absolute tracking error
//   TEC = sum h_k (v_k^2 + w_k^2)        [m^2/s + rad^2/s, numerically] control energy
//   ISE = sum h_k |e_k|^2 = T * ASE      [m^2 s] integral squared error, the integral itself
//   IAE = sum h_k |e_k|   = T * AAE      [m s]   integral absolute error
// with T = sum h_k and e = p_d - p_r. A collision is an episode: the step where a
// clearance turns negative after being >= 0 (or at the start) counts one.
//
// The e above is the controller's own error (measured target minus believed offset point).
// With a delayed or noisy sensor it differs from the true error e* = p_d(t) - p_r(t) (true
// target, true robot); true_ase, true_aae and max_true_error use e*. A *stall*: the target is
// reachable but not approached. The excess of a step is |e*| minus the best standoff (how far
// p_d(t) lies inside the zone of radius zone_radius + r_o of a disk: 0 when the target is
// reachable), so parking at the best standoff of an unreachable target is no stall. A step
// at t is stalled when the excess is > kStallError and over the last kStallWindow neither did
// the excess fall by kStallSpeed * kStallWindow nor did p_r move that far net (so chattering
// in place counts) -- where moving counts only while p_r has not gone more than half a turn
// round a disk in its current visit, or toward the target: an endless orbit stalls. A run of consecutive stalled steps t_a..t_b is a stall over
// [t_a - kStallWindow, t_b], of length t_b - t_a + kStallWindow. longest_stall is the longest
// (0 without any stalled step), stall_time the total.
//
// Orbits: while p_r stays within zone_radius + r_o + kOrbitReach of a disk's centre, the angle
// of p_r about it is accumulated; max_orbit_turns is the largest |angle| / 2 pi of such a
// visit (passing a disk gives about 0.5, circling it once 1). Toggles: steps where the escape
// (u_t != 0), or the avoidance (a disk in its band), switches on or off. Command jumps: the
// largest |v_k - v_(k-1)| and |w_k - w_(k-1)| between consecutive steps. Reversals: steps where
// w's sign is the opposite of the last w beyond +-kReversalDeadband (a command that hovers at
// zero does not count; one that swings through it does), and their rate per minute of run:
// the chatter a jump figure cannot see.
#pragma once

#include <cstdint>
#include <deque>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace sim {

// What one step shows the metrics.
struct MetricSample {
  double h = 0.0;                 // [s] time the command is held (0 for the last step)
  Eigen::Vector2d e = Eigen::Vector2d::Zero();  // tracking error p_d - p_r [m]
  double rho = 0.0;               // performance bound [m]; <= 0: the law has none
  core::Twist2 u;                       // applied command
  double diamond_norm = 0.0;      // |v|/v_max + |w|/w_max of the applied command
  double clearance_offset = std::numeric_limits<double>::infinity();  // [m]
  double clearance_body = std::numeric_limits<double>::infinity();    // [m]
  Eigen::Vector2d velocity_error = Eigen::Vector2d::Zero();  // true minus estimated target velocity [m/s]
  bool estimator_settled = false; // counts in the "after the transient" estimator figure
  bool valid = true;              // the controller produced a command
  bool saturated = false;
  bool envelope_widened = false;
  // Beyond the paper.
  Eigen::Vector2d e_true = Eigen::Vector2d::Zero();  // true error e* [m]
  double t = 0.0;                 // [s] time of the step
  Eigen::Vector2d p_r = Eigen::Vector2d::Zero();  // true offset point [m]
  bool conflict = false;          // e_hat^T u_c < 0 this step
  bool escaping = false;          // the tangential term was non-zero this step
  int passing_side = 0;           // its latched side (+1, -1; 0 released)
  bool avoiding = false;          // some disk in its detection band
  const std::vector<core::Disk>* obstacles = nullptr;  // where the disks are at t (orbits, standoff)
  double zone_radius = 0.0;       // [m] R or R + r: p_r's keep-out distance beyond a disk's radius
};

struct RunMetrics {
  double ase = 0.0;               // [m^2]
  double aae = 0.0;               // [m]
  double ise = 0.0;               // [m^2 s] integral of |e|^2 dt (ASE without the 1/T)
  double iae = 0.0;               // [m s] integral of |e| dt (AAE without the 1/T)
  double tec = 0.0;
  double max_e_over_rho = 0.0;
  double max_rho = 0.0;           // [m]
  double min_clearance_offset = std::numeric_limits<double>::infinity();  // [m]
  double min_clearance_body = std::numeric_limits<double>::infinity();    // [m]
  std::uint64_t offset_collisions = 0;  // contact episodes of the effective disk around p_r
  std::uint64_t body_collisions = 0;    // contact episodes of the body disk
  double offset_contact_time = 0.0;     // [s]
  double body_contact_time = 0.0;       // [s]
  std::uint64_t diamond_violations = 0; // steps with diamond_norm > 1 + 1e-9
  std::uint64_t nan_count = 0;          // steps with a non-finite value or an invalid output
  std::uint64_t saturated_steps = 0;
  std::uint64_t envelope_widenings = 0;
  double estimator_rms_error = 0.0;     // [m/s] time-RMS of |true - estimated velocity|
  double estimator_max_error_settled = 0.0;  // [m/s] max after the transient
  double final_error = 0.0;             // [m] |e| at the last step
  double sim_time = 0.0;                // [s] T
  std::uint64_t steps = 0;
  double true_ase = 0.0;                // [m^2] with the true error e*
  double true_aae = 0.0;                // [m]
  double true_ise = 0.0;                // [m^2 s] integral of |e*|^2 dt
  double true_iae = 0.0;                // [m s] integral of |e*| dt
  double max_true_error = 0.0;          // [m] peak |e*|
  double longest_stall = 0.0;           // [s]
  std::uint64_t conflict_steps = 0;     // steps with e_hat^T u_c < 0
  std::uint64_t escape_steps = 0;       // steps with a non-zero tangential term
  std::uint64_t side_flips = 0;         // steps whose passing side is the opposite of the last step's
  double stall_time = 0.0;              // [s] total length of the stalls
  double max_orbit_turns = 0.0;         // [-] largest |angle| / 2 pi of p_r about a disk in one visit
  std::uint64_t escape_toggles = 0;     // steps where the escape switched on or off
  std::uint64_t avoidance_toggles = 0;  // steps where the avoidance switched on or off
  double max_delta_v = 0.0;             // [m/s] largest per-step change of v
  double max_delta_omega = 0.0;         // [rad/s] largest per-step change of omega
  std::uint64_t omega_reversals = 0;    // sign reversals of omega (beyond the deadband)
  double omega_reversals_per_minute = 0.0;  // [1/min] omega_reversals / run time
};

class MetricsAccumulator {
 public:
  void add(const MetricSample& sample);
  // The figures so far (averages over the time accumulated; zero before any time).
  RunMetrics result() const;

 private:
  static double bestStandoff(const MetricSample& s);
  void addStall(const MetricSample& s, double excess);
  void addOrbits(const MetricSample& s);

  RunMetrics m_;
  double sum_e2_ = 0.0, sum_e_ = 0.0, sum_v2_ = 0.0, sum_true_e2_ = 0.0, sum_true_e_ = 0.0;
  // (t, p_r, excess) over the last window
  std::deque<std::pair<double, std::pair<Eigen::Vector2d, double>>> recent_;
  int last_side_ = 0;
  int last_omega_sign_ = 0;                                 // sign of the last omega beyond the deadband, 0 before
  double stall_start_ = -1.0;                               // t_a of the stall in progress, or < 0
  double last_stall_t_ = 0.0;                               // t of the last stalled step
  bool has_last_ = false, last_escaping_ = false, last_avoiding_ = false;
  core::Twist2 last_u_;
  std::vector<double> orbit_angle_;                         // per disk: accumulated angle of this visit [rad]
  std::vector<Eigen::Vector2d> orbit_last_;                 // per disk: last p_r - centre, zero when away
  bool circling_ = false;                                   // more than half a turn round a disk in this visit
  bool in_offset_contact_ = false, in_body_contact_ = false;
};

constexpr double kDiamondTolerance = 1e-9;
constexpr double kStallSpeed = 0.05;   // [m/s] net headway below this counts as standing
constexpr double kStallWindow = 0.5;   // [s] over which the headway is measured
constexpr double kStallError = 0.2;    // [m] twice the experiment's rho_inf: clearly not arrived
constexpr double kReversalDeadband = 0.01;  // [rad/s] |w| at or below this is no turn either way
constexpr double kOrbitReach = 0.5;    // [m] beyond a disk's zone where p_r's angle about it still counts

}  // namespace sim
}  // namespace amigobot_tracking
