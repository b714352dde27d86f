// sin(x)/x and (1 - cos(x))/x for the small turns of one step (|w| h), by their Taylor
// series: a few multiply-adds instead of a libm sin/cos pair, to rounding for |x| <= 0.25.
#pragma once

#include <cmath>

namespace amigobot_tracking {
namespace core {

// Below this |x| the series of sinc/cosc are exact to rounding (next term < 1e-18 relative).
constexpr double kSmallTurn = 0.25;

// sinc = sin(x)/x, cosc = (1 - cos(x))/x, so sin(x) = x sinc and cos(x) = 1 - x cosc.
inline void sincCosc(double x, double* sinc, double* cosc) {
  if (std::abs(x) <= kSmallTurn) {
    const double x2 = x * x;
    // Truncation after x^12 (sinc) and x^13 (cosc): |x|^14 / 15! < 3e-21 at |x| = 0.25.
    *sinc = 1.0 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880 +
             x2 * (-1.0 / 39916800 + x2 * (1.0 / 6227020800.0))))));
    *cosc = x * (0.5 + x2 * (-1.0 / 24 + x2 * (1.0 / 720 + x2 * (-1.0 / 40320 + x2 * (1.0 / 3628800 +
             x2 * (-1.0 / 479001600 + x2 * (1.0 / 87178291200.0)))))));
    return;
  }
  const double s = std::sin(x), c = std::cos(x);
  *sinc = s / x;
  *cosc = (1.0 - c) / x;
}

// (cos, sin) of theta + d from (c, s) = (cos, sin) of theta, for a small d.
inline void rotateBySmall(double d, double c, double s, double* c_out, double* s_out) {
  double sinc, cosc;
  sincCosc(d, &sinc, &cosc);
  const double sd = d * sinc, cd = 1.0 - d * cosc;
  *c_out = c * cd - s * sd;
  *s_out = s * cd + c * sd;
}

}  // namespace core
}  // namespace amigobot_tracking
