#include "amigobot_tracking/ros/recorded_run.h"

#include <cmath>

#include "amigobot_tracking/core/avoidance.h"
#include "amigobot_tracking/core/offset_point.h"
#include "amigobot_tracking/sim/json.h"
#include "amigobot_tracking/world/geometry.h"

namespace amigobot_tracking {
namespace ros_layer {

std::string RecordedRunConfig::validate() const {
  if (!(std::isfinite(robot_radius) && robot_radius > 0.0)) return "robot_radius must be > 0";
  if (!(std::isfinite(offset) && offset > 0.0)) return "offset must be > 0";
  if (!(std::isfinite(v_max) && v_max > 0.0)) return "v_max must be > 0";
  if (!(std::isfinite(w_max) && w_max > 0.0)) return "w_max must be > 0";
  const std::string bad_world = world::validateWorld(world);
  if (!bad_world.empty()) return "world: " + bad_world;
  return "";
}

RecordedRun::RecordedRun(RecordedRunConfig config) : config_(std::move(config)) {}

void RecordedRun::addTruth(double, const core::Pose2& pose) {
  truth_ = pose;
  have_truth_ = true;
  ++summary_.truth_samples;
}

void RecordedRun::addVirtualObstacles(std::vector<core::Disk> disks) {
  for (const core::Disk& d : disks) {
    bool known = false;
    for (const core::Disk& s : virtual_seen_) known = known || ((s.center - d.center).norm() < 1e-9 && s.radius == d.radius);
    if (!known) virtual_seen_.push_back(d);
  }
  virtual_ = std::move(disks);
  summary_.virtual_obstacles = std::max<std::uint64_t>(summary_.virtual_obstacles, virtual_.size());
}

std::vector<core::Disk> RecordedRun::allObstacles() const {
  std::vector<core::Disk> all = config_.world.obstacles;
  all.insert(all.end(), virtual_seen_.begin(), virtual_seen_.end());
  return all;
}

void RecordedRun::addCommand(double v, double w) {
  ++summary_.commands;
  const double norm = std::abs(v) / config_.v_max + std::abs(w) / config_.w_max;
  summary_.max_command_norm = std::max(summary_.max_command_norm, norm);
  if (!(norm <= 1.0 + sim::kDiamondTolerance)) ++summary_.command_violations;
}

void RecordedRun::addState(const TrackingState& s) {
  ++summary_.states;
  if (!s.enabled || !have_truth_) return;  // before enabling (or ground truth) there is no run to score
  const double stamp = s.header.stamp.toSec();
  if (t0_ < 0.0) t0_ = stamp;
  const double t = stamp - t0_;
  if (have_pending_) flush(t);

  const Eigen::Vector2d p_d(s.p_d.x, s.p_d.y), v_hat(s.v_hat.x, s.v_hat.y), e(s.e.x, s.e.y);
  Eigen::Vector2d v_d = Eigen::Vector2d::Zero();  // the target's true velocity, by finite difference
  if (have_previous_p_d_ && t > previous_t_) v_d = (p_d - previous_p_d_) / (t - previous_t_);
  previous_p_d_ = p_d;
  previous_t_ = t;
  have_previous_p_d_ = true;

  const Eigen::Vector2d body = truth_.position();
  const Eigen::Vector2d p_r_true = core::offsetPoint(truth_, config_.offset);
  const double clearance_world = world::clearance(config_.world, body, config_.robot_radius);
  const double clearance_virtual = core::clearance(body, config_.robot_radius, virtual_);
  summary_.min_clearance_world = std::min(summary_.min_clearance_world, clearance_world);
  summary_.min_clearance_virtual = std::min(summary_.min_clearance_virtual, clearance_virtual);
  if (have_path_pose_) summary_.path_length += (body - last_path_pose_.position()).norm();
  last_path_pose_ = truth_;
  have_path_pose_ = true;

  sim::MetricSample m;
  m.e = e;
  m.rho = s.rho;
  m.u = core::Twist2{s.v, s.omega};
  m.diamond_norm = std::abs(s.v) / config_.v_max + std::abs(s.omega) / config_.w_max;
  m.clearance_offset = std::min(world::clearance(config_.world, p_r_true, config_.robot_radius),
                                core::clearance(p_r_true, config_.robot_radius, virtual_));
  m.clearance_body = std::min(clearance_world, clearance_virtual);
  m.velocity_error = v_d - v_hat;
  m.estimator_settled = t > config_.settle_time;
  m.valid = s.valid;
  m.saturated = s.saturated;
  m.envelope_widened = s.envelope_widened;
  if (s.valid && s.rho > 0.0 && e.norm() < s.rho) ++within_rho_;

  pending_.t = t;
  pending_.sample = m;
  pending_.row = {t,          truth_.x,      truth_.y,      truth_.theta, s.p_r.x,   s.p_r.y,   p_d.x(),
                  p_d.y(),    p_d.x(),       p_d.y(),       v_hat.x(),    v_hat.y(), v_d.x(),   v_d.y(),
                  e.x(),      e.y(),         e.norm(),      s.rho,        s.v,       s.omega,   s.v_d,
                  s.omega_d,  s.u_c.x,       s.u_c.y,       m.clearance_offset,     m.clearance_body,
                  0.0,        s.saturated ? 1.0 : 0.0,      s.avoiding ? 1.0 : 0.0,
                  s.envelope_widened ? 1.0 : 0.0,           m.diamond_norm};
  have_pending_ = true;
}

void RecordedRun::flush(double next_t) {
  pending_.sample.h = std::max(0.0, next_t - pending_.t);
  pending_.row[26] = pending_.sample.h;
  accumulator_.add(pending_.sample);
  rows_.push_back(pending_.row);
  have_pending_ = false;
}

void RecordedRun::finish() {
  if (have_pending_) flush(pending_.t);  // the last step holds for no time
}

RecordedRunSummary RecordedRun::summary() const {
  RecordedRunSummary s = summary_;
  s.metrics = accumulator_.result();
  s.within_rho_fraction = s.metrics.steps > 0 ? static_cast<double>(within_rho_) / s.metrics.steps : 0.0;
  return s;
}

void to_json(sim::Json& j, const RecordedRunSummary& s) {
  using sim::jsonNumber;
  const sim::RunMetrics& m = s.metrics;
  j = {{"safe", !(s.collided() || s.command_violations > 0)}, {"ran", s.ran()}};
  j.update(sim::sharedMetricsJson(m));
  j.update(sim::Json{{"within_rho_fraction", jsonNumber(s.within_rho_fraction)},
                     {"min_clearance_world", jsonNumber(s.min_clearance_world)},
                     {"min_clearance_virtual", jsonNumber(s.min_clearance_virtual)},
                     {"commands", s.commands},
                     {"command_diamond_violations", s.command_violations},
                     {"max_command_diamond_norm", jsonNumber(s.max_command_norm)},
                     {"invalid_steps", m.nan_count},
                     {"tracking_time_s", jsonNumber(m.sim_time)},
                     {"path_length", jsonNumber(s.path_length)},
                     {"virtual_obstacles", s.virtual_obstacles},
                     {"truth_samples", s.truth_samples}});
}

std::string recordedRunJson(const RecordedRunSummary& summary, const RecordedRunConfig& config,
                            const std::vector<core::Disk>& all_obstacles, const std::string& name) {
  using sim::jsonNumber;
  sim::Json j = summary;
  sim::Json& s = j["scenario"];
  s["name"] = name;
  s["variant"] = "recorded";
  s["estimator"] = "paper";
  s["robot_radius"] = jsonNumber(config.robot_radius);
  s["offset"] = jsonNumber(config.offset);
  s["v_max"] = jsonNumber(config.v_max);
  s["w_max"] = jsonNumber(config.w_max);
  s["rho_inf"] = jsonNumber(config.rho_inf);
  s["obstacles"] = sim::Json::array();
  for (const core::Disk& d : all_obstacles) s["obstacles"].push_back(sim::obstacleJson(d, Eigen::Vector2d::Zero()));
  // The room for the plots: walls as [[x, y], [x, y]], polygons as their points.
  const auto xy = [](const Eigen::Vector2d& p) { return sim::Json::array({jsonNumber(p.x()), jsonNumber(p.y())}); };
  s["walls"] = sim::Json::array();
  for (const world::Segment& w : config.world.walls) s["walls"].push_back(sim::Json::array({xy(w.from), xy(w.to)}));
  s["polygons"] = sim::Json::array();
  for (const world::Polygon& p : config.world.polygons) {
    sim::Json points = sim::Json::array();
    for (const Eigen::Vector2d& v : p.points) points.push_back(xy(v));
    s["polygons"].push_back(points);
  }
  return sim::dumpJson(j);
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
