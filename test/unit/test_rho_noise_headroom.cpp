// (13')'s relaxation under measurement noise (recommended_law.cpp): it is weighed against
// rho less the noise headroom 5 sigma (rho_floor - rho_inf), so rho keeps that headroom above
// |e| at any height, not only at its floor: one noisy sample can move the measured |e| by it.
#include <gtest/gtest.h>

#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/law/recommended_law.h"

using namespace amigobot_tracking;

namespace {

core::RecommendedCommand blocked(double rho_floor) {
  core::ControllerConfig config;
  config.law = "recommended";
  const core::DiamondSet diamond(config.v_max, config.w_max);
  core::RecommendedInput in;
  in.pose = {0.0, 0.0, M_PI};  // facing away from the target: the applied command falls short
  in.p_r = {-config.offset, 0.0};
  in.e = {0.3, 0.0};
  in.v_hat = {0.3, 0.0};  // the target leaves at v_bar: more than the robot can close
  in.rho = 0.4;
  in.rho_floor = rho_floor;
  return core::recommendedCommand(config, diamond, in, {});
}

}  // namespace

TEST(RhoNoiseHeadroom, RelaxationCountsTheHeadroomTheNoiseNeeds) {
  const core::ControllerConfig config;
  const core::RecommendedCommand quiet = blocked(config.rho_inf);
  const core::RecommendedCommand noisy = blocked(config.rho_inf + 0.075);  // 5 sigma = 7.5 cm
  ASSERT_TRUE(quiet.valid && noisy.valid);
  ASSERT_GT(quiet.shortfall, 0.0);
  const double xi = 0.3 / 0.4, xi_n = 0.3 / (0.4 - 0.075);
  EXPECT_NEAR(quiet.relaxation, (1.0 + config.k_r) * xi * xi * quiet.shortfall, 1e-12);  // no noise: (13') as it was
  EXPECT_NEAR(noisy.relaxation, (1.0 + config.k_r) * xi_n * xi_n * noisy.shortfall, 1e-12);
  EXPECT_GT(noisy.relaxation, 1.4 * quiet.relaxation * noisy.shortfall / quiet.shortfall);
}

TEST(RhoNoiseHeadroom, WeightNeverExceedsOne) {
  // |e| inside the headroom band of rho: the weight saturates at 1, it does not blow up.
  core::ControllerConfig config;
  const core::DiamondSet diamond(config.v_max, config.w_max);
  core::RecommendedInput in;
  in.pose = {0.0, 0.0, M_PI};
  in.p_r = {-config.offset, 0.0};
  in.e = {0.35, 0.0};
  in.v_hat = {0.3, 0.0};
  in.rho = 0.4;
  in.rho_floor = config.rho_inf + 0.1;
  const core::RecommendedCommand c = core::recommendedCommand(config, diamond, in, {});
  ASSERT_TRUE(c.valid);
  EXPECT_NEAR(c.relaxation, (1.0 + config.k_r) * c.shortfall, 1e-12);
}
