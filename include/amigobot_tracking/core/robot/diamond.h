// The diamond-shaped input set U = {(v, w) : |v|/v_max + |w|/w_max <= 1} (paper eq. 2)
// and the saturation sigma of eq. (12).
#pragma once

#include <optional>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

// Wheel rim speeds [m/s] of a differential drive: left = v - b w, right = v + b w.
struct WheelSpeeds {
  double left = 0.0;
  double right = 0.0;
};

WheelSpeeds toWheelSpeeds(const Twist2& u, double half_track);
Twist2 fromWheelSpeeds(const WheelSpeeds& wheels, double half_track);

class DiamondSet {
 public:
  // Limits must be positive and finite (checked by the caller's config validation).
  DiamondSet(double v_max, double w_max);
  // The same set from the wheel speed limit alpha [m/s] and half wheel separation b [m]:
  // v_max = alpha, w_max = alpha / b, i.e. both wheels within +-alpha.
  static DiamondSet fromWheelLimit(double wheel_speed_max, double half_track);

  double vMax() const { return v_max_; }
  double wMax() const { return w_max_; }

  // |v|/v_max + |w|/w_max: <= 1 inside U. NaN for non-finite input.
  double normalizedNorm(const Twist2& u) const;
  bool contains(const Twist2& u, double tolerance = 0.0) const;

  // sigma(u) = u / max(1, |v|/v_max + |w|/w_max): unchanged inside U, otherwise scaled
  // radially onto the boundary, so the curvature v/w is kept. Returns nullopt for NaN or
  // infinite input: a caller must never turn that into a motion command.
  std::optional<Twist2> saturate(const Twist2& u) const;

 private:
  double v_max_;
  double w_max_;
};

}  // namespace core
}  // namespace amigobot_tracking
