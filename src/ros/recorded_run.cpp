#include "amigobot_tracking/ros/recorded_run.h"

#include <cmath>
#include <cstdio>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/law/law_registry.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/sim/json.h"
#include "amigobot_tracking/world/geometry.h"

namespace amigobot_tracking {
namespace ros_layer {

namespace {

// The laws a run is recorded with: the laws the robot runs and the registry's aliases
// ("escape": the paper's law with tangential_avoidance, a switch of the paper's, not a law).
std::vector<std::string> recordedLaws() {
  std::vector<std::string> laws = core::robotLawNames();
  for (const core::LawAlias& alias : core::lawAliases()) laws.push_back(alias.name);
  return laws;
}

bool isRecordedLaw(const std::string& law) {
  for (const std::string& name : recordedLaws())
    if (law == name) return true;
  return false;
}

std::string recordedLawList() { return core::lawNameList(recordedLaws()); }

}  // namespace

std::string RecordedRunConfig::validate() const {
  if (!(std::isfinite(robot_radius) && robot_radius > 0.0)) return "robot_radius must be > 0";
  if (!(std::isfinite(offset) && offset > 0.0)) return "offset must be > 0";
  if (!(std::isfinite(v_max) && v_max > 0.0)) return "v_max must be > 0";
  if (!(std::isfinite(w_max) && w_max > 0.0)) return "w_max must be > 0";
  const std::string bad_world = world::validateWorld(world);
  if (!bad_world.empty()) return "world: " + bad_world;
  if (!isRecordedLaw(law)) return "law must be one of " + recordedLawList() + ", got '" + law + "'";
  if (!(std::isfinite(velocity_window) && velocity_window > 0.0)) return "velocity_window must be > 0";
  const std::string verdict_error = verdict.validate();
  if (!verdict_error.empty()) return verdict_error;
  return "";
}

RecordedRun::RecordedRun(RecordedRunConfig config) : config_(std::move(config)), room_(world::worldAt(config_.world, 0.0)) {}

void RecordedRun::addTruth(double, const core::Pose2& pose, double world_t) {
  if (!config_.world.people.empty()) room_ = world::worldAt(config_.world, world_t);
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
  if (finished_ || !s.enabled || !have_truth_) return;  // before enabling (or ground truth) there is no run to score
  const double stamp = s.header.stamp.toSec();
  if (t0_ < 0.0) t0_ = stamp;
  const double t = stamp - t0_;

  const Eigen::Vector2d p_d(s.p_d.x, s.p_d.y), v_hat(s.v_hat.x, s.v_hat.y), e(s.e.x, s.e.y);
  // Clearance to everything solid (world) and virtual: the verdict's obstacle episodes.
  auto clearanceToAll = [&](const Eigen::Vector2d& p, double radius) {
    return std::min(world::clearance(room_, p, radius), core::clearance(p, radius, virtual_));
  };
  const Eigen::Vector2d body = truth_.position();
  const Eigen::Vector2d p_r_true = core::offsetPoint(truth_, config_.offset);
  const double clearance_world = world::clearance(room_, body, config_.robot_radius);  // people included
  for (std::size_t i = config_.world.obstacles.size(); i < room_.obstacles.size(); ++i) {  // worldAt appends them
    summary_.min_clearance_people = std::min(summary_.min_clearance_people,
                                             core::clearance(body, config_.robot_radius, {room_.obstacles[i]}));
  }
  const double clearance_virtual = core::clearance(body, config_.robot_radius, virtual_);
  summary_.min_clearance_world = std::min(summary_.min_clearance_world, clearance_world);
  summary_.min_clearance_virtual = std::min(summary_.min_clearance_virtual, clearance_virtual);
  if (have_path_pose_) summary_.path_length += (body - last_path_pose_.position()).norm();
  last_path_pose_ = truth_;
  have_path_pose_ = true;

  Step step;
  step.t = t;
  step.p_d = p_d;
  step.v_hat = v_hat;
  sim::MetricSample& m = step.sample;
  m.t = t;
  m.e = e;
  m.e_true = p_d - p_r_true;  // the target sample the controller used, the robot's true offset point
  m.p_r = p_r_true;
  m.rho = s.rho;
  m.u = core::Twist2{s.v, s.omega};
  m.diamond_norm = std::abs(s.v) / config_.v_max + std::abs(s.omega) / config_.w_max;
  m.clearance_offset = std::min(world::clearance(room_, p_r_true, config_.robot_radius),
                                core::clearance(p_r_true, config_.robot_radius, virtual_));
  m.clearance_body = std::min(clearance_world, clearance_virtual);
  m.estimator_settled = t > config_.settle_time;
  m.valid = s.valid;
  m.saturated = s.saturated;
  m.envelope_widened = s.envelope_widened;
  m.conflict = s.conflict;
  m.escaping = s.u_t.x != 0.0 || s.u_t.y != 0.0;
  m.passing_side = s.passing_side;
  if (s.valid && s.rho > 0.0 && e.norm() < s.rho) ++within_rho_;

  // A step without a controller output (stale pose or target) carries no target: not judged.
  const double effective_radius = config_.body_safe ? config_.robot_radius + config_.offset : config_.robot_radius;
  if (s.valid) tracking_.push_back(sim::TrackingSample{t, m.e_true.norm(), clearanceToAll(p_r_true, effective_radius),
                                          clearanceToAll(p_d, effective_radius)});
  // v_d_x/y (col 12, 13) and h (col 26) are filled by finish().
  step.row = {t,          truth_.x,      truth_.y,      truth_.theta, s.p_r.x,      s.p_r.y,      p_d.x(),
              p_d.y(),    p_d.x(),       p_d.y(),       v_hat.x(),    v_hat.y(),    0.0,          0.0,
              e.x(),      e.y(),         e.norm(),      s.rho,        s.v,          s.omega,      s.v_d,
              s.omega_d,  s.u_c.x,       s.u_c.y,       m.clearance_offset,         m.clearance_body,
              0.0,        s.saturated ? 1.0 : 0.0,      s.avoiding ? 1.0 : 0.0,
              s.envelope_widened ? 1.0 : 0.0,           m.diamond_norm,
              s.u_t.x,    s.u_t.y,       p_r_true.x(),  p_r_true.y(), static_cast<double>(s.passing_side)};
  steps_.push_back(step);
}

Eigen::Vector2d RecordedRun::targetVelocity(std::size_t k) const {
  // A 20 Hz finite difference of the sampled target is mostly sampling jitter (the control
  // step and the target's tf are not in phase); over a window it is the target's velocity.
  const double half = 0.5 * config_.velocity_window;
  std::size_t a = k, b = k;
  while (a > 0 && steps_[a - 1].t >= steps_[k].t - half) --a;
  while (b + 1 < steps_.size() && steps_[b + 1].t <= steps_[k].t + half) ++b;
  const double dt = steps_[b].t - steps_[a].t;
  return dt > 0.0 ? Eigen::Vector2d((steps_[b].p_d - steps_[a].p_d) / dt) : Eigen::Vector2d::Zero();
}

void RecordedRun::finish() {
  if (finished_) return;
  finished_ = true;
  for (std::size_t k = 0; k < steps_.size(); ++k) {
    Step& step = steps_[k];
    step.sample.h = k + 1 < steps_.size() ? std::max(0.0, steps_[k + 1].t - step.t) : 0.0;  // the last holds for no time
    const Eigen::Vector2d v_d = targetVelocity(k);
    step.sample.velocity_error = v_d - step.v_hat;
    step.row[12] = v_d.x();
    step.row[13] = v_d.y();
    step.row[26] = step.sample.h;
    accumulator_.add(step.sample);
    rows_.push_back(step.row);
  }
  summary_.tracking = sim::judgeTracking(tracking_, config_.verdict);
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
                     {"min_clearance_people", jsonNumber(s.min_clearance_people)},
                     {"commands", s.commands},
                     {"command_diamond_violations", s.command_violations},
                     {"max_command_diamond_norm", jsonNumber(s.max_command_norm)},
                     {"invalid_steps", m.nan_count},
                     {"tracking_time_s", jsonNumber(m.sim_time)},
                     {"path_length", jsonNumber(s.path_length)},
                     {"virtual_obstacles", s.virtual_obstacles},
                     {"truth_samples", s.truth_samples}});
  j.update(sim::pick(m, {"true_ase", "true_aae", "true_ise", "true_iae", "max_true_error", "longest_stall_s",
                         "conflict_steps", "escape_steps", "side_flips"}));
  j["saturated_fraction"] = jsonNumber(m.steps > 0 ? static_cast<double>(m.saturated_steps) / m.steps : 0.0);
  const sim::TrackingVerdict& v = s.tracking;
  sim::Json episodes = sim::Json::array();
  for (const sim::ObstacleEpisode& e : v.episodes) {
    episodes.push_back({{"start_s", jsonNumber(e.start)},
                        {"end_s", jsonNumber(e.end)},
                        {"peak_true_error", jsonNumber(e.peak_error)},
                        {"recovered_after_s", e.recovered_after < 0.0 ? sim::Json(nullptr) : jsonNumber(e.recovered_after)}});
  }
  j["tracking"] = {{"tracked", v.tracked},
                   {"reason", v.reason},
                   {"bound", jsonNumber(v.bound)},
                   {"max_judged_true_error", jsonNumber(v.max_judged_error)},
                   {"worst_time_s", jsonNumber(v.worst_time)},
                   {"judged_time_s", jsonNumber(v.judged_time)},
                   {"judged_fraction", jsonNumber(v.judged_fraction)},
                   {"judged_over_bound_time_s", jsonNumber(v.judged_over_bound_time)},
                   {"final_true_error", jsonNumber(v.final_error)},
                   {"episodes", episodes}};
}

std::string recordedRunJson(const RecordedRunSummary& summary, const RecordedRunConfig& config,
                            const std::vector<core::Disk>& all_obstacles, const std::string& name) {
  using sim::jsonNumber;
  sim::Json j = summary;
  j["law"] = config.law;
  const core::LawAlias* alias = core::findLawAlias(config.law);
  j["variant"] = alias ? alias->variant : config.law;
  sim::Json& tracking = j["tracking"];
  tracking["rho_inf"] = jsonNumber(config.verdict.rho_inf);
  tracking["tolerance"] = jsonNumber(config.verdict.tolerance);
  tracking["recovery_time_s"] = jsonNumber(config.verdict.recovery_time);
  tracking["band"] = jsonNumber(config.verdict.band);
  sim::Json& s = j["scenario"];
  s["name"] = name;
  s["variant"] = config.law;  // plot titles: [paper], [recommended] or [escape]
  s["law"] = config.law;
  s["estimator"] = "paper";
  char truth[96];
  std::snprintf(truth, sizeof truth, "central difference of the recorded target over %g s", config.velocity_window);
  s["velocity_truth"] = truth;
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
