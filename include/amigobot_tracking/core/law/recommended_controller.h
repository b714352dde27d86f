// The recommended law (recommended_law.h's command and (13')) as a ControlLaw: it keeps the
// law's own state, the feed-forward v_f (v_hat slew-limited to estimator.max_acceleration),
// its average over field_lookahead, the last command (the rate box's centre), the measured
// noise behind rho's floor and (13')'s relaxation, beside the shared estimator, start rule,
// envelope guard and pose-age compensation it inherits (bounded_law.h).
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "amigobot_tracking/core/law/bounded_law.h"
#include "amigobot_tracking/core/law/yield_rollout.h"

namespace amigobot_tracking {
namespace core {

class RecommendedController : public BoundedLaw {
 public:
  explicit RecommendedController(const ControllerConfig& config);

  std::unique_ptr<ControlLaw> clone() const override { return std::make_unique<RecommendedController>(*this); }
  std::string name() const override { return "recommended"; }
  ControllerOutput step(double t, const PoseSample& robot, const TargetSample& target,
                        const std::vector<Disk>& obstacles) override;

 private:
  void forgetLawState() override;
  // u from recommended_law.h into `out` (p_r, e, v_hat, rho set); false when not finite.
  bool command(const Pose2& pose, const std::vector<Disk>& obstacles, double h, ControllerOutput& out);
  void observeNoise(const TargetSample& target, bool jumped);
  double rhoFloor() const;

  double shortfall_ = 0.0;  // relaxation term of (13'), from the last step
  // The feed-forward: v_hat followed at most estimator.max_acceleration per second; NaN until
  // the first step.
  Eigen::Vector2d feed_forward_ = Eigen::Vector2d::Constant(NAN);
  Eigen::Vector2d smoothed_velocity_ = Eigen::Vector2d::Constant(NAN);  // v_f, first-order over field_lookahead
  Twist2 last_command_;  // the rate box is centred on it
  std::optional<YieldManoeuvre> committed_;  // the manoeuvre yielding to a person, as of the last step
  double since_yield_ = 0.0;                 // [s] since a step last yielded
  // The base as the law's own commands move it (config_.actuator): where the yielding
  // look-ahead starts its manoeuvres. Built at the first step.
  std::optional<ActuatorModel> base_;
  static constexpr double kYieldMemory = 1.0;  // [s] a commitment outlives the last yielding step this long
  // The noise estimate: the last target sample and the running mean of the squared
  // innovation of the samples against the feed-forward's prediction.
  double noise_variance_ = 0.0;
  double last_sample_stamp_ = NAN;
  Eigen::Vector2d last_sample_ = Eigen::Vector2d::Zero();
};

}  // namespace core
}  // namespace amigobot_tracking
