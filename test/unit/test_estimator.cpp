// Robust velocity estimator (3)-(4), discretised by backward Euler in eta = atanh(xi).
//
// Error bound after the transient, for a signal with |chi''| <= A sampled every h without
// noise: stage 2 guarantees |z1dot - z2| < rho_o, and stage 1 sits quasi-statically at
// F(xi1) = z1dot / a1 with F' >= 1, so its error e1 = rho_o xi1 changes at most at
// rho_o A / a1; the difference quotient of the samples is within h A / 2 of chi'. Hence
//     |chi' - z2| <= rho_o (1 + A / a1) + h A / 2      (tested with h A in place of h A / 2).
// With sample noise bounded by n the worst case adds 2 (n + rho_o) / h.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "amigobot_tracking/core/law/estimator.h"
#include "amigobot_tracking/core/reference/reference.h"

using namespace amigobot_tracking::core;

namespace {

struct Signal {
  std::function<double(double)> value;
  std::function<double(double)> rate;
  double max_accel;  // bound A on |chi''|
};

struct RunResult {
  double worst_velocity_error = 0.0;  // after the transient
  double worst_xi = 0.0;
};

// Samples the signal every h (plus bounded uniform noise), checks the guarantees at every
// step and returns the worst velocity error after `transient` seconds.
RunResult runAndCheck(const Signal& signal, double h, double duration, double noise = 0.0,
                      double transient = 0.5, EstimatorConfig config = EstimatorConfig()) {
  config.jump_threshold = 0.0;
  AxisEstimator est(config);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(-noise, noise);
  RunResult result;
  for (int k = 0; k * h <= duration; ++k) {
    const double t = k * h;
    const double chi = signal.value(t) + (noise > 0.0 ? uniform(rng) : 0.0);
    EXPECT_TRUE(est.update(t, chi));
    const double rho = est.bound(t);
    EXPECT_TRUE(std::isfinite(est.position()) && std::isfinite(est.velocity()));
    EXPECT_LT(std::abs(chi - est.position()), rho) << "stage 1 bound at t=" << t;
    if (k > 0) {
      EXPECT_LT(std::abs(est.stage1Rate() - est.velocity()), rho) << "stage 2 bound at t=" << t;
    }
    EXPECT_LT(std::abs(est.xi1()), 1.0);
    EXPECT_LT(std::abs(est.xi2()), 1.0);
    result.worst_xi = std::max({result.worst_xi, std::abs(est.xi1()), std::abs(est.xi2())});
    if (t > transient) {
      result.worst_velocity_error = std::max(result.worst_velocity_error, std::abs(signal.rate(t) - est.velocity()));
    }
  }
  return result;
}

double derivedBound(const Signal& s, double h, double noise = 0.0) {
  const EstimatorConfig c;
  return c.rho_o * (1.0 + s.max_accel / c.a1) + h * s.max_accel + 2.0 * (noise + (noise > 0 ? c.rho_o : 0.0)) / h;
}

Signal sinusoid(double amplitude, double freq) {
  return {[=](double t) { return amplitude * std::sin(freq * t); },
          [=](double t) { return amplitude * freq * std::cos(freq * t); }, amplitude * freq * freq};
}

Signal roseX() {
  auto rose = std::make_shared<RoseReference>(3.0, 3.0, 1.0);
  // |x''| of x = 3 cos 3t cos t: bounded by 3 (9 + 6 + 1) = 48; the true maximum is ~30.
  double max_accel = 0.0;
  for (double t = 0.0; t < 2 * M_PI; t += 1e-4) {
    max_accel = std::max(max_accel, std::abs((rose->at(t + 1e-5).velocity.x() - rose->at(t).velocity.x()) / 1e-5));
  }
  return {[rose](double t) { return rose->at(t).position.x(); }, [rose](double t) { return rose->at(t).velocity.x(); },
          max_accel};
}

}  // namespace

TEST(Estimator, SinusoidWithinDerivedBound) {
  for (double h : {1e-3, 1e-2}) {
    const Signal s = sinusoid(1.0, 2.0);
    const RunResult r = runAndCheck(s, h, 10.0);
    EXPECT_LT(r.worst_velocity_error, derivedBound(s, h)) << "h=" << h;
  }
}

TEST(Estimator, RampVelocityIsExactInSteadyState) {
  const Signal ramp{[](double t) { return 0.5 - 2.0 * t; }, [](double) { return -2.0; }, 0.0};
  for (double h : {1e-3, 1e-2, 1e-1}) {
    const RunResult r = runAndCheck(ramp, h, 10.0, 0.0, 2.0);
    EXPECT_LT(r.worst_velocity_error, 1e-6) << "h=" << h;
  }
}

TEST(Estimator, RoseCoordinateWithinDerivedBound) {
  const Signal s = roseX();
  EXPECT_GT(s.max_accel, 20.0);
  for (double h : {1e-3, 1e-2}) {
    const RunResult r = runAndCheck(s, h, 2 * M_PI);
    EXPECT_LT(r.worst_velocity_error, derivedBound(s, h)) << "h=" << h << " A=" << s.max_accel;
  }
}

TEST(Estimator, NoisySamplesKeepGuaranteesAndWorstCaseBound) {
  const Signal s = sinusoid(1.0, 1.0);
  for (double h : {1e-2, 1e-1}) {  // 100 Hz and 10 Hz with centimetre noise
    const RunResult r = runAndCheck(s, h, 20.0, 0.01);
    EXPECT_LT(r.worst_velocity_error, derivedBound(s, h, 0.01)) << "h=" << h;
  }
}

TEST(Estimator, StepWithoutJumpDetectionStaysBounded) {
  const Signal step{[](double t) { return t < 1.0 ? 0.0 : 2.0; }, [](double) { return 0.0; }, 0.0};
  const RunResult r = runAndCheck(step, 1e-2, 5.0, 0.0, 3.0);
  EXPECT_LT(r.worst_velocity_error, 0.05);  // settled again two seconds after the step
  EXPECT_LT(r.worst_xi, 1.0);
}

TEST(Estimator, JumpIsFollowedWithoutVelocitySpike) {
  EstimatorConfig config;
  config.jump_threshold = 0.5;
  AxisEstimator est(config);
  double worst_velocity = 0.0;
  for (int k = 0; k <= 300; ++k) {
    const double t = 0.01 * k;
    const double chi = 0.3 * t + (t >= 1.5 ? 2.0 : 0.0);  // relocalisation by 2 m at 1.5 s
    est.update(t, chi);
    EXPECT_LT(std::abs(chi - est.position()), est.bound(t));
    if (t > 0.5) worst_velocity = std::max(worst_velocity, std::abs(est.velocity() - 0.3));
  }
  EXPECT_EQ(est.jumps(), 1u);
  EXPECT_LT(worst_velocity, 0.02);
}

// A target faster than jump_threshold per sample, from rest (z2 = 0): the jump rule must not
// take every sample for a relocalisation (that kept v_hat at 0 for ever).
TEST(Estimator, FastTargetIsNotLockedByTheJumpRule) {
  struct Case {
    double speed, rate;
  };
  for (const Case& c : {Case{6.0, 10.0}, Case{12.0, 20.0}}) {
    AxisEstimator est;  // jump_threshold 0.5 m: 0.6 m per sample
    for (int k = 0; k <= 3 * c.rate; ++k) est.update(k / c.rate, c.speed * k / c.rate);
    EXPECT_NEAR(est.velocity(), c.speed, 0.05 * c.speed) << c.speed << " m/s at " << c.rate << " Hz";
    EXPECT_LE(est.jumps(), 1u);
  }
  // The paper's rose sampled every 60 ms from where it runs at 9 m/s (a reset mid-curve).
  const RoseReference rose(3.0, 3.0, 1.0);
  VelocityEstimator est;
  double worst = 0.0;
  for (int k = 0; k <= 105; ++k) {
    const double t = M_PI / 6 + 0.06 * k;
    const ReferenceState s = rose.at(t);
    est.update(t, s.position);
    if (t > M_PI / 6 + 1.0) worst = std::max(worst, (est.velocity() - s.velocity).norm() / 9.0);
  }
  EXPECT_LT(worst, 0.5);  // follows it (a 60 ms finite difference lags)
}

// The jump test is Euclidean: a diagonal relocalisation of (0.42, 0.42) m, 0.59 m, is a jump
// although each axis moves less than jump_threshold (per axis it gave v_hat ~ 4 m/s).
TEST(Estimator, DiagonalJumpIsCaughtOverBothAxes) {
  VelocityEstimator est;  // jump_threshold 0.5 m
  const Eigen::Vector2d v(0.2, 0.0);
  double worst = 0.0;
  for (int k = 0; k <= 80; ++k) {  // 20 Hz
    const double t = 0.05 * k;
    const Eigen::Vector2d p = v * t + (t >= 2.0 ? Eigen::Vector2d(0.42, 0.42) : Eigen::Vector2d::Zero());
    ASSERT_TRUE(est.update(t, p));
    if (t > 1.0) worst = std::max(worst, (est.velocity() - v).norm());
  }
  EXPECT_EQ(est.jumps(), 1u);
  EXPECT_LT(worst, 0.05);
}

// A relocalisation delivered over two samples (+0.6 m, +0.6 m) is one jump: its second part
// is not differentiated (v_hat 6 m/s for 0.2 s) and the next still sample is no false jump.
TEST(Estimator, RelocalisationOverTwoSamplesIsOneJump) {
  VelocityEstimator est;
  double worst = 0.0;
  for (int k = 0; k <= 100; ++k) {  // 20 Hz, a still target
    const double t = 0.05 * k;
    const double x = (k >= 40 ? 0.6 : 0.0) + (k >= 41 ? 0.6 : 0.0);
    ASSERT_TRUE(est.update(t, {x, 0.0}));
    if (t > 1.0) worst = std::max(worst, est.velocity().norm());
    EXPECT_LT((Eigen::Vector2d(x, 0.0) - est.position()).norm(), std::sqrt(2.0) * est.axisX().bound(t)) << t;
  }
  EXPECT_EQ(est.jumps(), 1u);
  EXPECT_LT(worst, 0.05);
}

// A target accelerating at 0.8 m/s^2 sampled at 1 Hz: its displacement per sample grows by
// 0.8 m, more than jump_threshold, but the rate changes by a_max h at most: motion, followed.
// (Before, every sample was a jump and v_hat froze at 0.39 m/s while the target reached 8 m/s.)
TEST(Estimator, AcceleratingTargetSampledSlowlyIsFollowed) {
  VelocityEstimator est;  // max_acceleration 1 m/s^2
  const double a = 0.8;
  for (int k = 0; k <= 10; ++k) ASSERT_TRUE(est.update(k, {0.5 * a * k * k, 0.0}));
  EXPECT_EQ(est.jumps(), 0u);
  EXPECT_GT(est.velocity().x(), 0.7 * a * 10.0) << "true speed " << a * 10.0 << " m/s";
  // The same course at a_max = 0.1 m/s^2 is still taken for jumps: the parameter is what lets it through.
  EstimatorConfig strict;
  strict.max_acceleration = 0.1;
  VelocityEstimator frozen(strict);
  for (int k = 0; k <= 10; ++k) ASSERT_TRUE(frozen.update(k, {0.5 * a * k * k, 0.0}));
  EXPECT_LT(frozen.velocity().x(), 0.5 * a * 10.0);
}

TEST(Estimator, LateAndNonFiniteSamplesAreIgnored) {
  AxisEstimator est;
  EXPECT_TRUE(est.update(1.0, 0.0));
  EXPECT_TRUE(est.update(1.1, 0.1));
  const double z1 = est.position(), z2 = est.velocity();
  EXPECT_FALSE(est.update(1.05, 5.0));  // late
  EXPECT_FALSE(est.update(1.1, 5.0));   // same stamp
  EXPECT_FALSE(est.update(1.2, std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(est.update(std::numeric_limits<double>::infinity(), 1.0));
  EXPECT_EQ(est.position(), z1);
  EXPECT_EQ(est.velocity(), z2);
  EXPECT_EQ(est.rejectedSamples(), 4u);
}

TEST(Estimator, RandomSequencesNeverLeaveTheBoundsOrProduceNaN) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> log_dt(-6.0, 1.0), log_mag(-3.0, 6.0), sign(-1.0, 1.0);
  for (int run = 0; run < 50; ++run) {
    EstimatorConfig config;
    config.jump_threshold = run % 2 ? 0.5 : 0.0;
    AxisEstimator est(config);
    double t = 0.0;
    for (int k = 0; k < 400; ++k) {
      t += std::pow(10.0, log_dt(rng));
      const double chi = sign(rng) * std::pow(10.0, log_mag(rng));
      ASSERT_TRUE(est.update(t, chi));
      ASSERT_TRUE(std::isfinite(est.position()) && std::isfinite(est.velocity()));
      ASSERT_LT(std::abs(est.xi1()), 1.0);
      ASSERT_LT(std::abs(est.xi2()), 1.0);
      ASSERT_LE(std::abs(chi - est.position()), est.bound(t) * (1.0 + 1e-12) + 1e-9 * std::abs(chi));
    }
  }
}

TEST(Estimator, ImplicitStageSolvesItsEquation) {
  for (double c : {1e-300, 1e-6, 0.005, 0.3, 2.0, 1e3, 1e12, 1e300}) {
    for (double k : {1e-9, 1e-3, 0.1, 10.0}) {
      for (double sgn : {1.0, -1.0}) {
        const double eta = solveImplicitStage(sgn * c, 0.01, k, 0.0);
        ASSERT_TRUE(std::isfinite(eta));
        ASSERT_LE(std::abs(eta), kMaxEta);
        EXPECT_EQ(eta >= 0.0, sgn > 0.0);
        if (std::abs(eta) < kMaxEta) {
          const double g = 0.01 * std::tanh(std::abs(eta)) + k * std::abs(eta) * std::pow(std::cosh(eta), 2);
          EXPECT_NEAR(g, c, 1e-9 * c + 1e-15) << "c=" << c << " k=" << k;
        }
      }
    }
  }
}

TEST(Estimator, ConvergesToTheContinuousSolutionAsSamplingGetsFaster) {
  // Reference: the same scheme at h = 1e-6 (first-order convergence => close to continuous).
  const Signal s = sinusoid(1.0, 2.0);
  auto velocityAt = [&](double h, double t_end) {
    AxisEstimator est;
    const int steps = static_cast<int>(std::llround(t_end / h));
    for (int k = 0; k <= steps; ++k) est.update(k * h, s.value(k * h));
    return est.velocity();
  };
  const double t_end = 1.0;
  const double reference = velocityAt(1e-6, t_end);
  const double err_coarse = std::abs(velocityAt(1e-3, t_end) - reference);
  const double err_fine = std::abs(velocityAt(1e-4, t_end) - reference);
  EXPECT_LT(err_coarse, 0.01);
  EXPECT_LT(err_fine, err_coarse / 5.0);
}

TEST(Estimator, Bdf2KeepsTheBoundsAndConvergesAtSecondOrder) {
  EstimatorConfig bdf2;
  bdf2.bdf2 = true;
  // The guarantees of every step hold as for backward Euler (runAndCheck asserts them).
  const Signal rose = roseX();
  for (double h : {1e-3, 1e-2}) {
    const RunResult r = runAndCheck(rose, h, 2 * M_PI, 0.0, 0.5, bdf2);
    EXPECT_LT(r.worst_velocity_error, derivedBound(rose, h)) << "h=" << h;
  }
  // Velocity error after the transient against a 1 us backward-Euler run (the continuous
  // solution to ~1e-6), on a sinusoid, with a variable step (h, 2h alternating).
  const Signal s = sinusoid(1.0, 3.0);
  auto velocityAt = [&](double h, double t_end, const EstimatorConfig& config) {
    AxisEstimator est(config);
    double t = 0.0;
    for (int k = 0; t < t_end - 1e-12; ++k) {
      est.update(t, s.value(t));
      t = std::min(t_end, t + (k % 2 ? 2.0 * h : h));
    }
    est.update(t_end, s.value(t_end));
    return est.velocity();
  };
  const double t_end = 1.0;
  const double reference = velocityAt(1e-6, t_end, EstimatorConfig());
  const double be_coarse = std::abs(velocityAt(4e-3, t_end, EstimatorConfig()) - reference);
  const double coarse = std::abs(velocityAt(4e-3, t_end, bdf2) - reference);
  const double fine = std::abs(velocityAt(2e-3, t_end, bdf2) - reference);
  EXPECT_LT(coarse, be_coarse / 5.0) << "BDF2 " << coarse << ", backward Euler " << be_coarse;
  EXPECT_LT(fine, coarse / 3.0) << "halving the step: " << coarse << " -> " << fine;  // ~1/4 at second order
}

TEST(Estimator, TwoAxesEstimateAPlanarVelocity) {
  VelocityEstimator est;
  const CircleReference circle({0.0, 0.0}, 1.0, 10.0);
  for (int k = 0; k <= 1000; ++k) est.update(0.01 * k, circle.at(0.01 * k).position);
  EXPECT_LT((est.velocity() - circle.at(10.0).velocity).norm(), 0.02);
  EXPECT_FALSE(est.update(5.0, {0.0, 0.0}));
  EXPECT_EQ(est.rejectedSamples(), 1u);
}

TEST(Estimator, ValidateNamesTheBadField) {
  EstimatorConfig c;
  EXPECT_EQ(c.validate(), "");
  c.a2 = 0.0;
  EXPECT_NE(c.validate().find("a2"), std::string::npos);
  c = EstimatorConfig();
  c.rho_o0 = 0.001;
  EXPECT_NE(c.validate().find("rho_o0"), std::string::npos);
}
