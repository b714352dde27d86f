// The transformation T of the performance function and the adaptive law (13) for rho.
#pragma once

#include <limits>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

// T(s) = atanh(s) = 0.5 ln((1+s)/(1-s)) for s in [0, 1).
double transformT(double s);
// J(s) = dT/ds = 1/(1 - s^2).
double transformJ(double s);

struct PerformanceGains {
  double decay_rate = 0.5;    // lambda [1/s]
  double rho_final = 0.1;     // rho_inf [m]
  double relax_gain = 0.5;    // k_r [-]
  // [m/s] cap of the relaxation term's rate; 0: none (the paper). Band chattering at a coarse
  // step feeds (13) a near-contact conflict (u_c ~ 1/margin) on every entry; the cap keeps rho
  // from jumping by metres in one step.
  double max_relaxation_rate = 0.0;
};

// rho' = -lambda (rho - rho_inf) - k_r min{0, T(|e|/rho) e_hat^T u_c - |u - u_d|}.
// The relaxation term (>= 0) is `relaxation`, the second argument of the minimum is
// `conflict` = T e_hat^T u_c - |u - u_d| (negative when constraints conflict).
double rhoRate(const PerformanceGains& gains, double rho, double conflict);

// One step of length h: the prescribed decay integrated exactly
// (rho_inf + (rho - rho_inf) e^(-lambda h)) plus the relaxation term held over
// min(h, max_relaxation) (the conflict was measured at the step's start only), at most
// max_relaxation_rate * h when that is > 0.
double rhoStep(const PerformanceGains& gains, double rho, double conflict, double h,
               double max_relaxation = std::numeric_limits<double>::infinity());

}  // namespace core
}  // namespace amigobot_tracking
