#include "amigobot_tracking/core/law/prescribed_performance.h"

#include <algorithm>
#include <cmath>

namespace amigobot_tracking {
namespace core {

double transformT(double s) { return std::atanh(s); }

double transformJ(double s) { return 1.0 / (1.0 - s * s); }

double rhoRate(const PerformanceGains& gains, double rho, double conflict) {
  return -gains.decay_rate * (rho - gains.rho_final) - gains.relax_gain * std::min(0.0, conflict);
}

double rhoStep(const PerformanceGains& gains, double rho, double conflict, double h, double max_relaxation) {
  const double decayed = gains.rho_final + (rho - gains.rho_final) * std::exp(-gains.decay_rate * h);
  double relaxation = -std::min(h, max_relaxation) * gains.relax_gain * std::min(0.0, conflict);
  if (gains.max_relaxation_rate > 0.0) relaxation = std::min(relaxation, gains.max_relaxation_rate * h);
  return decayed + relaxation;
}

}  // namespace core
}  // namespace amigobot_tracking
