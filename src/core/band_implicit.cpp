#include "amigobot_tracking/core/band_implicit.h"

#include <algorithm>
#include <cmath>

#include "amigobot_tracking/core/offset_point.h"

namespace amigobot_tracking {
namespace core {
namespace {

// The residual clearance_j(end of the step) - m' for a trial m', with what it implies.
class Residual {
 public:
  Residual(const BandImplicitProblem& p, const DiamondSet& diamond)
      : p_(p), v_max_(diamond.vMax()), w_max_(diamond.wMax()), cos_(std::cos(p.pose.theta)),
        sin_(std::sin(p.pose.theta)), contact_(p.robot_radius + p.obstacle.radius) {
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
    return (1.0 / std::max(m, p_.min_margin) - 1.0 / p_.delta) * (m + contact_) * normal_;
  }

  double operator()(double m) const {
    const Eigen::Vector2d u_r = p_.rest + p_.k_o * term(m);
    // (11) then (12): G(theta)^-1 u_r, scaled radially into the diamond.
    const Twist2 u_d = offsetVelocityToTwist(u_r, Eigen::Vector2d(cos_, sin_), p_.offset);
    double v = u_d.v, w = u_d.omega;
    const double norm = std::abs(v) / v_max_ + std::abs(w) / w_max_;
    if (norm > 1.0) {
      v /= norm;
      w /= norm;
    }
    // The exact arc under the held command: centre and heading at the end, then p_r there.
    const double turn = w * p_.h;
    const double st = std::sin(turn), ct = std::cos(turn);
    // sin(turn)/turn and (1 - cos(turn))/turn, by series for small turns.
    const bool small = std::abs(turn) < 1e-4;
    const double sinc = small ? 1.0 - turn * turn / 6.0 : st / turn;
    const double cosc = small ? 0.5 * turn * (1.0 - turn * turn / 12.0) : (1.0 - ct) / turn;
    const double run = v * p_.h;
    const double cos_end = cos_ * ct - sin_ * st, sin_end = sin_ * ct + cos_ * st;
    const Eigen::Vector2d end(p_.pose.x + run * (cos_ * sinc - sin_ * cosc) + p_.offset * cos_end,
                              p_.pose.y + run * (sin_ * sinc + cos_ * cosc) + p_.offset * sin_end);
    return (end - p_.obstacle.center).norm() - contact_ - m;
  }

 private:
  const BandImplicitProblem& p_;
  double v_max_, w_max_, cos_, sin_, contact_;
  Eigen::Vector2d normal_;
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
  // Bracket: the distance changes at most by the path length h * speed.
  double lo = 0.0, hi = m0 + p.h * maxOffsetSpeed(diamond, p.offset) + 1e-12;
  double f_lo = residual(lo), f_hi = residual(hi);
  if (!(f_lo > 0.0) || !(f_hi < 0.0)) return result;
  constexpr double kTolerance = 1e-10;  // [m] on the residual and on the bracket
  int side = 0;
  double m = lo;
  for (int iter = 1; iter <= 100; ++iter) {
    result.iterations = iter;
    m = (f_lo * hi - f_hi * lo) / (f_lo - f_hi);
    if (!(m > lo && m < hi)) m = 0.5 * (lo + hi);
    const double f = residual(m);
    if (std::abs(f) <= kTolerance || hi - lo <= kTolerance) break;
    if (f > 0.0) {
      lo = m;
      f_lo = f;
      if (side == 1) f_hi *= 0.5;  // Illinois: the same end twice, halve the other's weight
      side = 1;
    } else {
      hi = m;
      f_hi = f;
      if (side == -1) f_lo *= 0.5;
      side = -1;
    }
  }
  result.solved = true;
  result.end_clearance = m;
  result.u_c = residual.term(m);
  return result;
}

}  // namespace core
}  // namespace amigobot_tracking
