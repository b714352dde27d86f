#include "amigobot_tracking/core/reference/reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "amigobot_tracking/core/support/small_angle.h"

namespace amigobot_tracking {
namespace core {

RoseReference::RoseReference(double amplitude, double k, double time_scale)
    : amplitude_(amplitude), k_(k), rate_(1.0 / time_scale) {}

ReferenceState RoseReference::at(double t) const {
  const double phase = rate_ * t;
  return state(std::cos(phase), std::sin(phase), std::cos(k_ * phase), std::sin(k_ * phase));
}

ReferenceState RoseReference::state(double c, double s, double ck, double sk) const {
  const double petal = amplitude_ * ck;
  const double petal_rate = -amplitude_ * k_ * rate_ * sk;
  ReferenceState out;
  out.position = {petal * c, petal * s};
  out.velocity = {petal_rate * c - petal * rate_ * s, petal_rate * s + petal * rate_ * c};
  return out;
}

void RoseReference::atPair(double t0, double t1, ReferenceState* s0, ReferenceState* s1) const {
  const double phase = rate_ * t0;
  const double c0 = std::cos(phase), sn0 = std::sin(phase);
  const double ck0 = std::cos(k_ * phase), sk0 = std::sin(k_ * phase);
  *s0 = state(c0, sn0, ck0, sk0);
  // At t1 both phases are rotations of t0's by small angles (series, small_angle.h).
  const double d = rate_ * (t1 - t0);
  double c1, sn1, ck1, sk1;
  rotateBySmall(d, c0, sn0, &c1, &sn1);
  rotateBySmall(k_ * d, ck0, sk0, &ck1, &sk1);
  *s1 = state(c1, sn1, ck1, sk1);
}

CircleReference::CircleReference(const Eigen::Vector2d& center, double radius, double period)
    : center_(center), radius_(radius), rate_(2.0 * M_PI / period) {}

ReferenceState CircleReference::at(double t) const {
  const double phase = rate_ * t;
  ReferenceState s;
  s.position = center_ + radius_ * Eigen::Vector2d(std::cos(phase), std::sin(phase));
  s.velocity = radius_ * rate_ * Eigen::Vector2d(-std::sin(phase), std::cos(phase));
  return s;
}

SplineReference::SplineReference(const std::vector<Eigen::Vector2d>& waypoints, double duration)
    : points_(waypoints) {
  if (waypoints.size() < 2) throw std::invalid_argument("spline needs at least 2 waypoints");
  if (!(duration > 0.0)) throw std::invalid_argument("spline duration must be > 0");
  const size_t n = points_.size();
  knots_.assign(n, 0.0);
  for (size_t i = 1; i < n; ++i) knots_[i] = knots_[i - 1] + (points_[i] - points_[i - 1]).norm();
  if (!(knots_.back() > 0.0)) throw std::invalid_argument("spline waypoints are all the same point");
  for (double& knot : knots_) knot *= duration / knots_.back();
  for (size_t i = 1; i < n; ++i) {
    if (!(knots_[i] > knots_[i - 1])) throw std::invalid_argument("spline has two equal consecutive waypoints");
  }
  // Natural spline: tridiagonal system for the second derivatives (Thomas algorithm).
  second_.assign(n, Eigen::Vector2d::Zero());
  if (n == 2) return;
  std::vector<double> diag(n, 1.0), upper(n, 0.0);
  std::vector<Eigen::Vector2d> rhs(n, Eigen::Vector2d::Zero());
  for (size_t i = 1; i + 1 < n; ++i) {
    const double h0 = knots_[i] - knots_[i - 1], h1 = knots_[i + 1] - knots_[i];
    const double lower = h0;
    diag[i] = 2.0 * (h0 + h1);
    upper[i] = h1;
    rhs[i] = 6.0 * ((points_[i + 1] - points_[i]) / h1 - (points_[i] - points_[i - 1]) / h0);
    const double m = lower / diag[i - 1];
    diag[i] -= m * upper[i - 1];
    rhs[i] -= m * rhs[i - 1];
  }
  for (size_t i = n - 2; i >= 1; --i) second_[i] = (rhs[i] - upper[i] * second_[i + 1]) / diag[i];
  // A step tiny next to the others overflows the curvature: refuse rather than return NaN.
  for (const Eigen::Vector2d& m : second_) {
    if (!m.allFinite()) throw std::invalid_argument("spline waypoint steps too uneven (a step near zero)");
  }
}

ReferenceState SplineReference::at(double t) const {
  ReferenceState s;
  if (t >= knots_.back()) {
    s.position = points_.back();
    return s;
  }
  t = std::max(t, 0.0);
  const size_t i = std::min<size_t>(std::upper_bound(knots_.begin(), knots_.end(), t) - knots_.begin() - 1,
                                    knots_.size() - 2);
  const double h = knots_[i + 1] - knots_[i];
  const double a = (knots_[i + 1] - t) / h, b = (t - knots_[i]) / h;
  const Eigen::Vector2d& m0 = second_[i];
  const Eigen::Vector2d& m1 = second_[i + 1];
  s.position = a * points_[i] + b * points_[i + 1] + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * (h * h / 6.0);
  s.velocity = (points_[i + 1] - points_[i]) / h + ((1.0 - 3.0 * a * a) * m0 + (3.0 * b * b - 1.0) * m1) * (h / 6.0);
  return s;
}

}  // namespace core
}  // namespace amigobot_tracking
