#include "amigobot_tracking/core/law/band_implicit.h"

#include <algorithm>
#include <cmath>

#include "amigobot_tracking/core/support/small_angle.h"

namespace amigobot_tracking {
namespace core {
namespace {

// The residual clearance_j(end of the step) - m' for a trial m', with what it implies.
class Residual {
 public:
  Residual(const BandImplicitProblem& p, const DiamondSet& diamond)
      : p_(p), inv_v_max_(1.0 / diamond.vMax()), inv_w_max_(1.0 / diamond.wMax()), inv_offset_(1.0 / p.offset),
        inv_delta_(1.0 / p.delta), contact_(p.robot_radius + p.obstacle.radius) {
    if (std::isnan(p.start_heading.x())) {
      cos_ = std::cos(p.pose.theta);
      sin_ = std::sin(p.pose.theta);
    } else {
      cos_ = p.start_heading.x();
      sin_ = p.start_heading.y();
    }
    if (!std::isnan(p.command_heading.x())) {
      command_heading_ = p.command_heading;
    } else if (std::isnan(p.command_theta)) {
      command_heading_ = Eigen::Vector2d(cos_, sin_);
    } else {
      command_heading_ = Eigen::Vector2d(std::cos(p.command_theta), std::sin(p.command_theta));
    }
    const Eigen::Vector2d p_r(p.pose.x + p.offset * cos_, p.pose.y + p.offset * sin_);
    const Eigen::Vector2d away = p_r - p.obstacle.center;
    const double distance = away.norm();
    normal_ = distance > 1e-9 ? Eigen::Vector2d(away / distance) : Eigen::Vector2d(-cos_, -sin_);
    start_clearance_ = distance - contact_;
  }

  double startClearance() const { return start_clearance_; }

  // Obstacle j's term of (10) at clearance m (zero beyond the band).
  Eigen::Vector2d term(double m) const {
    if (m > p_.delta) return Eigen::Vector2d::Zero();
    return (1.0 / std::max(m, p_.min_margin) - inv_delta_) * (m + contact_) * normal_;
  }

  double operator()(double m) const {
    const Eigen::Vector2d u_r = p_.rest + p_.k_o * term(m);
    // (11) then (12): G(theta)^-1 u_r, scaled radially into the diamond.
    // (Reciprocals precomputed: the residual is evaluated ~6 times per step.)
    const Eigen::Vector2d& c = command_heading_;
    double v = c.x() * u_r.x() + c.y() * u_r.y();
    double w = (c.x() * u_r.y() - c.y() * u_r.x()) * inv_offset_;
    const double norm = std::abs(v) * inv_v_max_ + std::abs(w) * inv_w_max_;
    if (norm > 1.0) {
      const double scale = 1.0 / norm;
      v *= scale;
      w *= scale;
    }
    // The exact arc under the held command: centre and heading at the end, then p_r there.
    const double turn = w * p_.h;
    // sin(turn)/turn and (1 - cos(turn))/turn, by series for the small turns of a step.
    double sinc, cosc;
    sincCosc(turn, &sinc, &cosc);
    const double st = turn * sinc, ct = 1.0 - turn * cosc;
    const double run = v * p_.h;
    const double cos_end = cos_ * ct - sin_ * st, sin_end = sin_ * ct + cos_ * st;
    const Eigen::Vector2d end(p_.pose.x + run * (cos_ * sinc - sin_ * cosc) + p_.offset * cos_end,
                              p_.pose.y + run * (sin_ * sinc + cos_ * cosc) + p_.offset * sin_end);
    return (end - p_.obstacle.center).norm() - contact_ - m;
  }

 private:
  const BandImplicitProblem& p_;
  double inv_v_max_, inv_w_max_, inv_offset_, inv_delta_, cos_ = 1.0, sin_ = 0.0, contact_;
  Eigen::Vector2d normal_, command_heading_;
  double start_clearance_ = 0.0;
};

}  // namespace

double maxOffsetSpeed(const DiamondSet& diamond, double offset) {
  // |p_r'| = sqrt(v^2 + r^2 w^2) is convex in (v, w): its maximum over the diamond is at a vertex.
  return std::max(diamond.vMax(), offset * diamond.wMax());
}

BandImplicitResult solveBandImplicit(const BandImplicitProblem& p, const DiamondSet& diamond) {
  const Residual residual(p, diamond);
  BandImplicitResult result;
  const double m0 = residual.startClearance();
  result.end_clearance = m0;
  result.u_c = residual.term(m0);  // the explicit term, kept when there is no bracket
  if (!(p.h > 0.0) || !(m0 > 0.0)) return result;
  // Bracket: the residual is < 0 at hi (the distance changes at most by the path length
  // h * speed, so no evaluation is needed there) and must be > 0 at 0.
  double lo = 0.0, hi = m0 + p.h * maxOffsetSpeed(diamond, p.offset) + 1e-12;
  if (!(residual(lo) > 0.0)) return result;
  constexpr double kTolerance = 1e-9;  // [m] on the residual and on the bracket
  // Secant from two points by the start clearance (sliding along a disk, the end clearance is
  // close to it), kept inside the bracket: a step leaving it, or a flat secant, bisects.
  double x0 = std::min(m0, 0.5 * (lo + hi)), x1 = x0 + 1e-4;
  double f0 = residual(x0);
  double m = x0;
  for (int iter = 1; iter <= 100; ++iter) {
    result.iterations = iter;
    (f0 > 0.0 ? lo : hi) = x0;
    if (std::abs(f0) <= kTolerance || hi - lo <= kTolerance) {
      m = x0;
      break;
    }
    if (!(x1 > lo && x1 < hi)) x1 = 0.5 * (lo + hi);
    const double f1 = residual(x1);
    m = x1;
    double next = f1 != f0 ? x1 - f1 * (x1 - x0) / (f1 - f0) : 0.5 * (lo + hi);
    x0 = x1;
    f0 = f1;
    x1 = next;
  }
  result.solved = true;
  result.end_clearance = m;
  result.u_c = residual.term(m);
  return result;
}

}  // namespace core
}  // namespace amigobot_tracking
