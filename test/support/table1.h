// Table 1 of the paper (its simulation study, Section 5.1) as a controller config, for the
// unit tests that run the paper's own numbers: the paper's radius (body_safe false).
#pragma once

#include "amigobot_tracking/core/law/controller_config.h"

inline amigobot_tracking::core::ControllerConfig table1Config() {
  amigobot_tracking::core::ControllerConfig c;
  c.robot_radius = 0.2;
  c.offset = 0.3;
  c.v_max = c.w_max = 5.0;
  c.delta = 0.016;
  c.k_d = 3.0;
  c.k_o = 1.0;
  c.k_r = 0.5;
  c.lambda = 5.0;
  c.rho_inf = 0.1;
  c.rho_0 = 1.84;
  c.body_safe = false;
  return c;
}
