// ControllerConfig::validate names the first bad field by its table key.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "amigobot_tracking/core/law/controller_config.h"

using namespace amigobot_tracking::core;

namespace {

void expectRejected(const std::function<void(ControllerConfig&)>& spoil, const std::string& field) {
  ControllerConfig c;
  spoil(c);
  const std::string err = c.validate();
  EXPECT_FALSE(err.empty()) << "accepted a bad " << field;
  EXPECT_EQ(err.rfind(field, 0), 0u) << "message does not start with '" << field << "': " << err;
}

}  // namespace

TEST(ControllerConfig, DefaultsAreValid) { EXPECT_EQ(ControllerConfig().validate(), ""); }

TEST(ControllerConfig, RejectsEachBadField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectRejected([](ControllerConfig& c) { c.robot_radius = 0.0; }, "robot_radius");
  expectRejected([](ControllerConfig& c) { c.robot_radius = 1e308; }, "robot_radius");  // <= 100 m
  expectRejected([](ControllerConfig& c) { c.offset = -0.3; }, "offset");
  expectRejected([](ControllerConfig& c) { c.offset = 0.0; }, "offset");
  expectRejected([](ControllerConfig& c) { c.v_max = 0.0; }, "v_max");
  expectRejected([=](ControllerConfig& c) { c.w_max = nan; }, "w_max");
  expectRejected([](ControllerConfig& c) { c.k_d = -1.0; }, "k_d");
  expectRejected([](ControllerConfig& c) { c.k_o = 0.0; }, "k_o");
  expectRejected([](ControllerConfig& c) { c.k_r = 0.0; }, "k_r");
  expectRejected([](ControllerConfig& c) { c.lambda = 0.0; }, "lambda");
  expectRejected([](ControllerConfig& c) { c.rho_inf = 0.0; }, "rho_inf");
  expectRejected([](ControllerConfig& c) { c.rho_0 = c.rho_inf; }, "rho_0");
  expectRejected([](ControllerConfig& c) { c.delta = 0.0; }, "delta");
  expectRejected([](ControllerConfig& c) { c.delta = std::numeric_limits<double>::infinity(); }, "delta");
  expectRejected([](ControllerConfig& c) { c.max_error_ratio = 1.0; }, "max_error_ratio");
  expectRejected([](ControllerConfig& c) { c.min_margin = c.delta; }, "min_margin");
  expectRejected([](ControllerConfig& c) { c.estimator.a1 = 0.0; }, "estimator/a1");
  expectRejected([](ControllerConfig& c) { c.estimator.a2 = -2.0; }, "estimator/a2");
  expectRejected([](ControllerConfig& c) { c.estimator.lambda_o = 0.0; }, "estimator/lambda_o");
  expectRejected([](ControllerConfig& c) { c.estimator.rho_o = 0.0; }, "estimator/rho_o");
  expectRejected([](ControllerConfig& c) { c.estimator.rho_o0 = 0.001; }, "estimator/rho_o0");
  expectRejected([](ControllerConfig& c) { c.estimator.jump_threshold = -1.0; }, "estimator/jump_threshold");
}

TEST(ControllerConfig, MessageNamesTheValue) {
  ControllerConfig c;
  c.k_d = -2.5;
  EXPECT_NE(c.validate().find("-2.5"), std::string::npos);
}

TEST(ControllerConfig, EffectiveRadius) {
  ControllerConfig c;
  c.body_safe = false;
  EXPECT_DOUBLE_EQ(c.effectiveRadius(), c.robot_radius);
  c.body_safe = true;
  EXPECT_DOUBLE_EQ(c.effectiveRadius(), c.robot_radius + c.offset);
}
