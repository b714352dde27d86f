#include "amigobot_tracking/core/law/estimator.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace amigobot_tracking {
namespace core {
const FieldTable<EstimatorConfig>& estimatorFields() {
  using E = EstimatorConfig;
  static const FieldTable<E> table = {
      field("a1", &E::a1, "1/s", "velocity estimator's stage-1 gain, eq. (3): z1 follows the target sample",
            positive()),
      field("a2", &E::a2, "1/s",
            "velocity estimator's stage-2 gain, eq. (4): z2, the velocity estimate v_hat, follows stage 1's rate",
            positive()),
      field("lambda_o", &E::lambda_o, "1/s", "decay rate of the velocity estimator's bounds rho_o(t)", positive()),
      field("rho_o", &E::rho_o, "m and m/s",
            "steady-state bound of both velocity-estimator stages (position, velocity)",
            positive()),
      field("rho_o0", &E::rho_o0, "m and m/s",
            "initial bound rho_o(0) of both velocity-estimator stages at each (re)start, >= rho_o", positive()),
      field("jump_threshold", &E::jump_threshold, "m",
            "a target sample farther than this from the prediction (and from the last motion repeated) is a "
            "relocalisation jump: the estimator moves with it instead of differentiating it; 0: off",
            nonNegative()),
      field("max_acceleration", &E::max_acceleration, "m/s^2",
            "the target's rate may change by this times the sample interval per sample: the jump rule's tolerance "
            "(1 Hz samples of a 0.8 m/s^2 target are motion), and the recommended law's feed-forward follows v_hat "
            "no faster (0: no bound there)",
            nonNegative()),
  };
  return table;
}

std::string EstimatorConfig::validate() const {
  const std::string bad = checkFields(estimatorFields(), *this);
  if (!bad.empty()) return bad;
  std::ostringstream err;
  if (rho_o0 < rho_o) err << "rho_o0: must be >= rho_o = " << rho_o << ", got " << rho_o0;
  return err.str();
}

double estimatorBound(const EstimatorConfig& config, double elapsed) {
  return (config.rho_o0 - config.rho_o) * std::exp(-config.lambda_o * std::max(0.0, elapsed)) +
         config.rho_o;
}

double solveImplicitStage(double c, double rho, double k, double eta_guess, double* tanh_eta) {
  if (c == 0.0) {
    if (tanh_eta) *tanh_eta = 0.0;
    return 0.0;
  }
  // g is odd: solve g(eta) = |c| on eta >= 0 and restore the sign.
  const double sign = c > 0.0 ? 1.0 : -1.0;
  const double target = std::abs(c);
  struct Eval {
    double g, dg, d2g, tanh;
  };
  // exp(2 eta) of the last evaluation: later iterates are within ~1e-4 of it, where
  // exp(2 eta) = e2_last exp(2 d) takes a short series instead of another exp().
  double eta_last = 0.0, e2_last = 1.0;
  auto eval = [&](double eta) {
    const double d = 2.0 * (eta - eta_last);
    double e2;
    if (std::abs(d) <= 1e-3) {  // truncation after d^5: < 2e-21 relative
      e2 = e2_last + e2_last * (d * (1.0 + d * (0.5 + d * (1.0 / 6 + d * (1.0 / 24 + d * (1.0 / 120))))));
    } else {
      e2 = std::exp(2.0 * eta);
    }
    eta_last = eta;
    e2_last = e2;
    // One division for 1/e2 and 1/(e2 + 1).
    const double q = 1.0 / (e2 * (e2 + 1.0));
    const double inv_e2 = (e2 + 1.0) * q;
    const double cosh2 = 0.25 * (e2 + 2.0 + inv_e2);  // cosh^2(eta)
    const double tanh = (e2 - 1.0) * (e2 * q);
    const double sech2 = 1.0 - tanh * tanh;  // 1 / cosh^2(eta)
    const double sinh_2 = 0.5 * (e2 - inv_e2);  // sinh(2 eta)
    const double cosh_2 = 0.5 * (e2 + inv_e2);  // cosh(2 eta)
    return Eval{rho * tanh + k * eta * cosh2 - target, rho * sech2 + k * (cosh2 + eta * sinh_2),
                -2.0 * rho * sech2 * tanh + 2.0 * k * (sinh_2 + eta * cosh_2), tanh};
  };
  auto done = [&](double eta, double tanh) {
    if (tanh_eta) *tanh_eta = sign * tanh;
    return sign * eta;
  };
  // Bracket: k*eta <= g(eta) gives eta <= c/k. Past kMaxEta the root is capped.
  double lo = 0.0;
  double hi = target / k;
  if (hi >= kMaxEta) {
    if (eval(kMaxEta).g <= 0.0) return done(kMaxEta, std::tanh(kMaxEta));
    hi = kMaxEta;
  }
  // Halley's step (g'' costs nothing once exp(2 eta) is known) converges cubically: after a
  // step s the root is within about C s^3, C = |g'''/6g' - (g''/2g')^2| <= ~1 here (tanh and
  // cosh^2 terms), so a step below 1e-4 min(eta, 1) leaves the new iterate within ~1e-12
  // min(eta, 1)^3 of the root (relative to eta below 1, like Newton's old 1e-6 (1 + eta)
  // stop): about half the warm starts then need one evaluation, most of the rest two.
  constexpr double kHalleyStep = 1e-4;
  double eta = std::clamp(sign * eta_guess, lo, hi);
  for (int iter = 0; iter < 60; ++iter) {
    const Eval v = eval(eta);
    if (v.g > 0.0) hi = eta; else lo = eta;
    const double denominator = 2.0 * v.dg * v.dg - v.g * v.d2g;
    double next = denominator > 0.0 ? eta - 2.0 * v.g * v.dg / denominator : eta - v.g / v.dg;
    const double step = next - eta;
    // A converged step lands on the bracket end just set to eta: keep it (bisecting there
    // threw the root away and cost ~3 extra iterations per solve).
    const bool settled = std::abs(step) <= kHalleyStep * std::min(std::abs(next), 1.0);
    if (settled) {
      // tanh(eta + s) by its Taylor series in s (derivatives of tanh: 1 - T^2, -2T (1 - T^2),
      // (1 - T^2)(6T^2 - 2)), no division; the dropped term is ~(1 - T^2) s^4: rounding.
      const double t = v.tanh, sech2 = 1.0 - t * t;
      return done(next, t + sech2 * step * (1.0 + step * (-t + step * (t * t - 1.0 / 3))));
    }
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // the step left the bracket: bisect.
    if (hi - lo <= 1e-15) return done(next, std::tanh(next));
    eta = next;
  }
  return done(eta, std::tanh(eta));
}

void JumpRule::reset(const Eigen::Vector2d& chi, const Eigen::Vector2d& rate) {
  last_chi_ = chi;
  motion_rate_ = episode_rate_ = rate;
  episode_length_ = 0;
}

JumpDecision JumpRule::decide(const EstimatorConfig& config, double h, const Eigen::Vector2d& chi,
                              const Eigen::Vector2d& z2) {
  JumpDecision d;
  const Eigen::Vector2d previous = last_chi_;
  const Eigen::Vector2d rate = (chi - previous) / h;
  last_chi_ = chi;
  const double threshold = config.jump_threshold;
  // The rate may change by a_max h per sample: the repeated motion is uncertain by a_max h^2.
  const double tolerance = threshold + config.max_acceleration * h * h;
  const bool jumped = threshold > 0.0 && (chi - (previous + z2 * h)).norm() > threshold &&
                      (chi - (previous + motion_rate_ * h)).norm() > tolerance;
  if (!jumped) {
    episode_length_ = 0;
    motion_rate_ = rate;
    return d;
  }
  // Consecutive jumping samples are one relocalisation; motion_rate_ stays the motion before it.
  const bool repeats = episode_length_ > 0 && ((rate - episode_rate_) * h).norm() <= tolerance;
  if (episode_length_ == 0) ++jumps_;
  episode_length_ = repeats ? episode_length_ + 1 : 1;
  episode_rate_ = rate;
  if (episode_length_ >= 3) {  // the same displacement three times: steady motion, not a jump
    --jumps_;
    episode_length_ = 0;
    motion_rate_ = rate;
    d.kind = JumpDecision::kRestart;
    d.rate = rate;
    return d;
  }
  d.kind = JumpDecision::kJump;
  d.shift = chi - (previous + z2 * h);
  return d;
}

AxisEstimator::AxisEstimator(const EstimatorConfig& config) : config_(config) {}

void AxisEstimator::reset(double t, double chi, double velocity_guess) {
  initialized_ = true;
  t0_ = last_t_ = t;
  z1_ = chi;
  z2_ = velocity_guess;
  z1_rate_ = velocity_guess;
  jump_rule_.reset({chi, 0.0}, {velocity_guess, 0.0});
  eta1_ = eta2_ = 0.0;
  eta1_change_ = eta2_change_ = eta1_change_before_ = eta2_change_before_ = last_h_ = h_before_ = 0.0;
  z1_prev_ = z2_prev_ = 0.0;
  has_prev_ = false;
}

bool AxisEstimator::update(double t, double chi) { return update(t, chi, bound(t)); }

bool AxisEstimator::update(double t, double chi, double bound_at_t) {
  if (initialized_ && std::isfinite(chi) && t > last_t_ && std::isfinite(t)) {
    const JumpDecision d = jump_rule_.decide(config_, t - last_t_, {chi, 0.0}, {z2_, 0.0});
    return update(t, chi, bound_at_t, d.kind, d.shift.x(), d.rate.x());
  }
  return update(t, chi, bound_at_t, JumpDecision::kMotion, 0.0, 0.0);
}

bool AxisEstimator::update(double t, double chi, double bound_at_t, JumpDecision::Kind kind, double shift,
                           double rate) {
  if (!std::isfinite(t) || !std::isfinite(chi)) {
    ++rejected_;
    return false;
  }
  if (!initialized_) {
    reset(t, chi);
    return true;
  }
  const double h = t - last_t_;
  if (!(h > 0.0)) {
    ++rejected_;
    return false;
  }
  if (kind == JumpDecision::kRestart) {  // steady motion the jump rule took for a jump: start over at its rate
    reset(t, chi, rate);
    return true;
  }
  const double rho = bound_at_t;
  if (kind == JumpDecision::kJump) {
    z1_ += shift;  // relocalisation: move with the jump (error kept), do not differentiate it
    z1_prev_ += shift;
  }
  // y' = a y + a_prev y_prev + b h f(y'): backward Euler (1, 0, 1) or BDF2 for the step ratio w.
  double a = 1.0, a_prev = 0.0, b = 1.0;
  const double w = last_h_ > 0.0 ? h / last_h_ : 0.0;
  if (config_.bdf2 && has_prev_ && w <= 2.4) {
    b = (1.0 + w) / (1.0 + 2.0 * w);
    a = (1.0 + w) * b;
    a_prev = -w * w / (1.0 + 2.0 * w);
  }
  double xi = 0.0;  // tanh(eta), from the solver
  // Warm start: the quadratic through the last three etas (Newton form), at t.
  auto guess = [&](double eta, double change, double change_before) {
    if (!(last_h_ > 0.0) || w > 4.0) return eta;
    const double slope = change / last_h_;
    if (!(h_before_ > 0.0)) return eta + h * slope;
    const double curvature = (slope - change_before / h_before_) / (last_h_ + h_before_);
    return eta + h * slope + curvature * h * (h + last_h_);
  };
  // Stage 1: z1 follows chi; its rate over the step is the scheme's derivative at t.
  const double base1 = a * z1_ + a_prev * z1_prev_;
  const double eta1 =
      solveImplicitStage(chi - base1, rho, b * h * config_.a1, guess(eta1_, eta1_change_, eta1_change_before_), &xi);
  eta1_change_before_ = eta1_change_;
  eta1_change_ = eta1 - eta1_;
  eta1_ = eta1;
  const double z1_next = chi - rho * xi;
  z1_rate_ = (z1_next - base1) / (b * h);
  z1_prev_ = z1_;
  z1_ = z1_next;
  // Stage 2: z2 follows z1's rate.
  const double base2 = a * z2_ + a_prev * z2_prev_;
  const double eta2 = solveImplicitStage(z1_rate_ - base2, rho, b * h * config_.a2,
                                        guess(eta2_, eta2_change_, eta2_change_before_), &xi);
  eta2_change_before_ = eta2_change_;
  eta2_change_ = eta2 - eta2_;
  eta2_ = eta2;
  z2_prev_ = z2_;
  z2_ = z1_rate_ - rho * xi;
  has_prev_ = true;
  h_before_ = last_h_;
  last_h_ = h;
  last_t_ = t;
  return true;
}

double AxisEstimator::xi1() const { return std::tanh(eta1_); }
double AxisEstimator::xi2() const { return std::tanh(eta2_); }

VelocityEstimator::VelocityEstimator(const EstimatorConfig& config) : x_(config), y_(config) {}

void VelocityEstimator::reset(double t, const Eigen::Vector2d& position, const Eigen::Vector2d& velocity_guess) {
  x_.reset(t, position.x(), velocity_guess.x());
  y_.reset(t, position.y(), velocity_guess.y());
  jump_rule_.reset(position, velocity_guess);
}

bool VelocityEstimator::update(double t, const Eigen::Vector2d& position) {
  if (!std::isfinite(t) || !position.allFinite() || (x_.initialized() && !(t > x_.lastStamp()))) {
    ++rejected_;  // reject the sample as a whole so both axes stay in step
    return false;
  }
  if (!x_.initialized()) {
    reset(t, position);
    return true;
  }
  const double bound = x_.bound(t);  // both axes share rho_o(t)
  const JumpDecision d = jump_rule_.decide(x_.config(), t - x_.lastStamp(), position, velocity());
  const bool ok_x = x_.update(t, position.x(), bound, d.kind, d.shift.x(), d.rate.x());
  const bool ok_y = y_.update(t, position.y(), bound, d.kind, d.shift.y(), d.rate.y());
  return ok_x && ok_y;
}

}  // namespace core
}  // namespace amigobot_tracking
