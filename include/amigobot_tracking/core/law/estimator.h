// Robust velocity estimator (tracking differentiator) of the paper, eqs. (3)-(4).
//
// Discretisation: one backward-Euler (implicit) step per measurement, over the time since
// the previous sample, written in the unbounded coordinate eta = atanh(xi). Each stage
// solves, for its new eta,
//     rho(t+h) * tanh(eta) + h * a * eta * cosh(eta)^2 = c,   c = input - state
// (the left side is odd and strictly increasing in eta, so the root is unique for every
// c and every h > 0) and then sets state = input - rho(t+h) * tanh(eta). The bound
// |input - state| < rho(t+h) therefore holds by construction for any step size and any
// input, and xi = tanh(eta) stays strictly inside (-1, 1) (|eta| is capped at 18, where
// tanh is still below 1 in double precision). Backward Euler is L-stable, which the
// stiff dynamics need (the paper uses ode15s): explicit schemes blow up at 10 Hz.
// Convergence to the continuous solution is first order in h.
//
// With bdf2 (offline simulation only; the robot keeps backward Euler) each stage takes a
// variable-step BDF2 step instead: y' = a y + a_prev y_prev + b h f(y'), which has the same
// scalar equation (c = input - a y - a_prev y_prev, k = b h gain), the same bound by
// construction and is L-stable too, but second order: stage 1's rate is BDF2's derivative,
// so v_hat no longer lags the target by half a step. The first step, and a step more than
// 2.4x the previous one (BDF2's zero-stability limit is 1 + sqrt 2), are backward Euler.
//
// Stage 1 tracks the sample chi with z1; its rate over the step, z1dot = (z1' - z1)/h,
// is the input of stage 2, whose state z2 is the velocity estimate.
//
// Jumps (JumpRule below): a sample farther than jump_threshold (Euclidean, over the whole
// position, not per axis) both from the prediction chi_prev + z2 h and from the last motion
// repeated, chi_prev + w h (w the rate of the last sample judged motion, the repeat widened by
// max_acceleration h^2: the rate may change by a_max h per sample, so an accelerating target
// sampled slowly is motion, not a jump on every sample), is a relocalisation: z1 is translated
// by it instead of differentiating it, so the velocity estimate does not spike. Consecutive
// jumping samples are one jump (a relocalisation delivered over several samples), and w is the
// motion before it, so the next still sample is not a false jump. Three consecutive jumping
// samples of the same displacement are motion after all (a target faster than jump_threshold
// per sample): the estimator restarts at that rate and the episode is not counted.
// Late samples (stamp not after the last one) are ignored and counted.
#pragma once

#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace core {

struct EstimatorConfig {
  double a1 = 1.0;              // [1/s] stage-1 gain.
  double a2 = 1.0;              // [1/s] stage-2 gain.
  double lambda_o = 30.0;       // [1/s] decay rate of the estimator's bounds rho_oi(t).
  double rho_o = 0.01;          // steady-state bound of both stages ([m], [m/s]).
  double rho_o0 = 1.0;          // initial bound rho_oi(0) of both stages.
  double jump_threshold = 0.5;  // [m] a sample this far from the prediction is a jump; 0 = off.
  double max_acceleration = 1.0;  // [m/s^2] a_max: the rate may change by a_max h per sample (jump rule).
  bool bdf2 = false;            // second-order BDF2 steps (offline simulation); false: backward Euler.

  bool operator==(const EstimatorConfig& o) const {
    return a1 == o.a1 && a2 == o.a2 && lambda_o == o.lambda_o && rho_o == o.rho_o && rho_o0 == o.rho_o0 &&
           jump_threshold == o.jump_threshold &&
           max_acceleration == o.max_acceleration && bdf2 == o.bdf2;
  }

  // Empty when valid, otherwise "key: reason" for the first bad field (the table's bounds,
  // then rho_o0 >= rho_o).
  std::string validate() const;
};

// The fields read from parameters and scenarios (bdf2 follows the simulator's integrator).
const FieldTable<EstimatorConfig>& estimatorFields();

// rho_o(t) = (rho_o(0) - rho_o) exp(-lambda_o t) + rho_o.
double estimatorBound(const EstimatorConfig& config, double elapsed);

// One implicit step of a stage: returns eta solving rho*tanh(eta) + k*eta*cosh(eta)^2 = c
// with k = h * gain > 0. Pure; exposed for tests. With tanh_eta, also writes tanh(eta)
// (from the solver's last evaluation, to rounding: the caller needs no tanh of its own).
double solveImplicitStage(double c, double rho, double k, double eta_guess, double* tanh_eta = nullptr);

// Maximum |eta| used (tanh(18) < 1 in double precision).
constexpr double kMaxEta = 18.0;

// What the jump rule made of one sample.
struct JumpDecision {
  enum Kind { kMotion, kJump, kRestart } kind = kMotion;
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // kJump: chi - (chi_prev + z2 h), added to z1
  Eigen::Vector2d rate = Eigen::Vector2d::Zero();   // kRestart: the steady rate found
};

// The jump rule of the header comment on a 2-D position (the 1-D estimator uses y = 0).
class JumpRule {
 public:
  void reset(const Eigen::Vector2d& chi, const Eigen::Vector2d& rate);
  // The sample chi after h > 0, with the velocity estimate z2 before it.
  JumpDecision decide(const EstimatorConfig& config, double h, const Eigen::Vector2d& chi,
                      const Eigen::Vector2d& z2);
  std::uint64_t jumps() const { return jumps_; }

 private:
  Eigen::Vector2d last_chi_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d motion_rate_ = Eigen::Vector2d::Zero();   // w: the last motion's rate
  Eigen::Vector2d episode_rate_ = Eigen::Vector2d::Zero();  // rate of the last jumping sample
  int episode_length_ = 0;                                  // consecutive jumping samples
  std::uint64_t jumps_ = 0;
};

// Estimator of one scalar signal and its derivative.
class AxisEstimator {
 public:
  explicit AxisEstimator(const EstimatorConfig& config = EstimatorConfig());

  // Starts at sample chi taken at time t: z1 = chi, z2 = velocity_guess.
  void reset(double t, double chi, double velocity_guess = 0.0);
  // Feeds one sample; returns false (and changes nothing) when it is not newer than the
  // last one or not finite. The first sample resets the estimator.
  bool update(double t, double chi);
  // The same with the bound rho_o(t) already computed (the 2-D wrapper shares it between axes).
  bool update(double t, double chi, double bound_at_t);
  // The same with the jump rule's decision taken outside (the 2-D wrapper, over both axes).
  bool update(double t, double chi, double bound_at_t, JumpDecision::Kind kind, double shift, double rate);

  bool initialized() const { return initialized_; }
  double position() const { return z1_; }        // z1
  double velocity() const { return z2_; }        // z2
  double stage1Rate() const { return z1_rate_; } // z1dot over the last step
  double xi1() const;
  double xi2() const;
  double lastStamp() const { return last_t_; }
  double bound(double t) const { return estimatorBound(config_, t - t0_); }  // rho_o1 = rho_o2
  std::uint64_t jumps() const { return jump_rule_.jumps(); }
  std::uint64_t rejectedSamples() const { return rejected_; }
  const EstimatorConfig& config() const { return config_; }
  JumpRule& jumpRule() { return jump_rule_; }

 private:
  EstimatorConfig config_;
  bool initialized_ = false;
  double t0_ = 0.0;
  double last_t_ = 0.0;
  double z1_ = 0.0;
  double z2_ = 0.0;
  double z1_rate_ = 0.0;
  double eta1_ = 0.0;
  double eta2_ = 0.0;
  // Changes of eta over the last two steps and their lengths: the solver's warm start is the
  // quadratic through the last three values (one Newton iteration fewer per solve on smooth
  // inputs than the last value).
  double eta1_change_ = 0.0, eta1_change_before_ = 0.0;
  double eta2_change_ = 0.0, eta2_change_before_ = 0.0;
  double last_h_ = 0.0, h_before_ = 0.0;
  double z1_prev_ = 0.0;  // z1 and z2 one sample back (BDF2), valid when has_prev_
  double z2_prev_ = 0.0;
  bool has_prev_ = false;
  JumpRule jump_rule_;  // its own (1-D) unless the 2-D wrapper decides
  std::uint64_t rejected_ = 0;
};

// The 2-D wrapper: one AxisEstimator for x and one for y of the target position.
class VelocityEstimator {
 public:
  explicit VelocityEstimator(const EstimatorConfig& config = EstimatorConfig());

  void reset(double t, const Eigen::Vector2d& position,
             const Eigen::Vector2d& velocity_guess = Eigen::Vector2d::Zero());
  bool update(double t, const Eigen::Vector2d& position);

  bool initialized() const { return x_.initialized(); }
  Eigen::Vector2d position() const { return {x_.position(), y_.position()}; }
  Eigen::Vector2d velocity() const { return {x_.velocity(), y_.velocity()}; }
  double lastStamp() const { return x_.lastStamp(); }
  const AxisEstimator& axisX() const { return x_; }
  const AxisEstimator& axisY() const { return y_; }
  std::uint64_t jumps() const { return jump_rule_.jumps(); }
  std::uint64_t rejectedSamples() const { return rejected_; }

 private:
  AxisEstimator x_;
  AxisEstimator y_;
  JumpRule jump_rule_;  // Euclidean: one decision for both axes
  std::uint64_t rejected_ = 0;
};

}  // namespace core
}  // namespace amigobot_tracking
