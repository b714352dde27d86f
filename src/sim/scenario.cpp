#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/robot_description.h"

#include <cmath>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/core/input_file.h"
#include "amigobot_tracking/core/offset_point.h"
#include "amigobot_tracking/sim/scenario_fields.h"

namespace amigobot_tracking {
namespace sim {
namespace {

constexpr double kMinWaypointStep = 1e-3;  // [m]

[[noreturn]] void fail(const std::string& file, const YAML::Node& node, const std::string& key,
                       const std::string& reason) {
  std::ostringstream msg;
  msg << file;
  if (node.IsDefined() && node.Mark().line >= 0) msg << ":" << node.Mark().line + 1;
  msg << ": " << key << ": " << reason;
  throw ScenarioError(msg.str());
}

std::string describe(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

// A YAML mapping whose keys are read one by one; finish() refuses the keys never read.
class Section {
 public:
  Section(const YAML::Node& node, std::string path, const std::string& file)
      : node_(node), path_(std::move(path)), file_(file) {
    if (!node.IsMap()) fail(file_, node, path_, "expected a mapping {key: value, ...}, got " + describe(node));
    for (const auto& item : node_) {
      if (!item.first.IsScalar()) fail(file_, item.first, key("(key)"), "a key must be a word, got " + describe(item.first));
    }
  }

  std::string key(const std::string& name) const { return path_.empty() ? name : path_ + "." + name; }
  bool has(const std::string& name) const { return node_[name].IsDefined() && !node_[name].IsNull(); }

  YAML::Node required(const std::string& name) {
    used_.insert(name);
    const YAML::Node value = node_[name];
    if (!value.IsDefined() || value.IsNull()) fail(file_, node_, key(name), "missing (required)");
    return value;
  }
  YAML::Node optional(const std::string& name) {
    used_.insert(name);
    return node_[name];
  }

  double number(const std::string& name) { return toNumber(required(name), key(name)); }
  double number(const std::string& name, double fallback) {
    return has(name) ? toNumber(optional(name), key(name)) : (used_.insert(name), fallback);
  }
  bool boolean(const std::string& name) { return toBool(required(name), key(name)); }
  bool boolean(const std::string& name, bool fallback) {
    return has(name) ? toBool(optional(name), key(name)) : (used_.insert(name), fallback);
  }
  std::string text(const std::string& name) { return toText(required(name), key(name)); }
  std::string text(const std::string& name, const std::string& fallback) {
    return has(name) ? toText(optional(name), key(name)) : (used_.insert(name), fallback);
  }
  std::vector<double> numbers(const std::string& name, size_t count) {
    return toNumbers(required(name), key(name), count);
  }
  Eigen::Vector2d point(const std::string& name) {
    const std::vector<double> v = numbers(name, 2);
    return {v[0], v[1]};
  }

  void finish() const {
    for (const auto& item : node_) {
      const std::string name = item.first.Scalar();  // a word: checked by the constructor
      if (!used_.count(name)) fail(file_, item.first, key(name), "unknown key (misspelt?)");
    }
  }

  double toNumber(const YAML::Node& node, const std::string& where) const {
    double value = 0.0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value))
      fail(file_, node, where, "expected a number, got " + describe(node));
    if (!std::isfinite(value)) fail(file_, node, where, "must be finite, got " + describe(node));
    return value;
  }
  bool toBool(const YAML::Node& node, const std::string& where) const {
    bool value = false;
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value))
      fail(file_, node, where, "expected true or false, got " + describe(node));
    return value;
  }
  std::string toText(const YAML::Node& node, const std::string& where) const {
    if (!node.IsScalar()) fail(file_, node, where, "expected a word, got " + describe(node));
    return node.Scalar();
  }
  std::vector<double> toNumbers(const YAML::Node& node, const std::string& where, size_t count) const {
    if (!node.IsSequence() || node.size() != count)
      fail(file_, node, where, "expected a list of " + std::to_string(count) + " numbers, got " + describe(node));
    std::vector<double> out;
    for (size_t i = 0; i < count; ++i) out.push_back(toNumber(node[i], where + "[" + std::to_string(i) + "]"));
    return out;
  }
  const std::string& file() const { return file_; }
  const YAML::Node& node() const { return node_; }

 private:
  YAML::Node node_;
  std::string path_;
  const std::string& file_;
  std::set<std::string> used_;
};

double positive(Section& s, const std::string& name, double value) {
  if (!(value > 0.0)) fail(s.file(), s.node()[name], s.key(name), "must be > 0, got " + std::to_string(value));
  return value;
}

// Reads the rows of `table` that `nameOf` places in this section (their YAML names; "" for
// rows of other sections): type, bounds, and whether the key is required.
template <class C, class NameOf>
void readSection(Section& s, const core::FieldTable<C>& table, C& config, NameOf&& nameOf) {
  for (const core::Field<C>& f : table) {
    const std::string name = nameOf(f.key);
    if (name.empty()) continue;
    if (!s.has(name)) {
      if (requiredScenarioKey(s.key(name))) s.required(name);  // throws "missing (required)"
      s.optional(name);
      continue;
    }
    const YAML::Node node = s.optional(name);
    core::FieldValue value;
    switch (f.type) {
      case core::FieldType::kReal: value = s.toNumber(node, s.key(name)); break;
      case core::FieldType::kBoolean: value = s.toBool(node, s.key(name)); break;
      case core::FieldType::kText: value = s.toText(node, s.key(name)); break;
      case core::FieldType::kInteger: {
        const double v = s.toNumber(node, s.key(name));
        if (v != std::floor(v) || std::abs(v) > 2e9)
          fail(s.file(), node, s.key(name), "expected an integer, got " + describe(node));
        value = static_cast<int>(v);
        break;
      }
    }
    const std::string why = core::checkValue(f.type, f.bounds, value);
    if (!why.empty()) fail(s.file(), node, s.key(name), why);
    f.set(config, value);
  }
}

// The controller's rows of one section (robot or controller) under their scenario names.
void readControllerFields(Section& s, const std::string& section, core::ControllerConfig& c) {
  readSection(s, core::controllerFields(), c, [&](const std::string& key) {
    const std::string path = scenarioPath(key);
    return path.rfind(section + ".", 0) == 0 ? path.substr(section.size() + 1) : std::string();
  });
}

// The scenario's own rows ("simulation/duration") of one section.
void readScenarioFields(Section& s, const std::string& section, Scenario& scenario) {
  readSection(s, scenarioFields(), scenario, [&](const std::string& key) {
    return key.rfind(section + "/", 0) == 0 ? key.substr(section.size() + 1) : std::string();
  });
}

void parseRobot(Section s, Scenario& scenario) {
  sim::ClosedLoopSetup& setup = scenario.setup;
  readControllerFields(s, "robot", setup.controller);
  readScenarioFields(s, "robot", scenario);
  if (!scenario.robot_description.empty()) {
    std::string path = scenario.robot_description;
    const size_t slash = scenario.file.find_last_of('/');
    if (path[0] != '/' && slash != std::string::npos) path = scenario.file.substr(0, slash + 1) + path;
    setup.dynamics = loadRobotDynamics(path);
  }
  setup.dynamics.ideal = scenario.dynamics == "ideal";
  const std::vector<double> pose = s.numbers("initial_pose", 3);
  setup.initial_pose = {pose[0], pose[1], pose[2]};
  s.finish();
}

void parseController(Section s, sim::ClosedLoopSetup& setup) {
  core::ControllerConfig& c = setup.controller;
  readControllerFields(s, "controller", c);
  const std::string variant = s.text("variant", "paper");
  try {
    setup.law = parseControlLaw(variant);
  } catch (const std::invalid_argument& e) {
    fail(s.file(), s.node()["variant"], s.key("variant"), e.what());
  }
  const std::string estimator = s.text("estimator", "paper");
  try {
    setup.velocity_source = parseVelocitySource(estimator);
  } catch (const std::invalid_argument& e) {
    fail(s.file(), s.node()["estimator"], s.key("estimator"), e.what());
  }
  // The proportional baseline's default gain: the paper law's small-error stiffness at
  // rho = rho_inf, k_d / rho_inf (T(s) ~ s).
  setup.baseline.k_p = positive(s, "k_p", s.number("k_p", c.k_d / c.rho_inf));
  setup.baseline.lowpass_tau = positive(s, "lowpass_tau", s.number("lowpass_tau", setup.baseline.lowpass_tau));
  setup.baseline.kalman_accel_std =
      positive(s, "kalman_accel_std", s.number("kalman_accel_std", setup.baseline.kalman_accel_std));
  setup.baseline.kalman_measurement_std =
      positive(s, "kalman_measurement_std", s.number("kalman_measurement_std", setup.baseline.kalman_measurement_std));
  s.finish();
}

ReferenceSpec parseReference(Section s) {
  ReferenceSpec r;
  r.type = s.text("type");
  if (r.type == "rose") {
    r.amplitude = positive(s, "amplitude", s.number("amplitude"));
    r.k = positive(s, "k", s.number("k"));
    r.time_scale = positive(s, "time_scale", s.number("time_scale", 1.0));
  } else if (r.type == "circle") {
    r.center = s.point("center");
    r.radius = positive(s, "radius", s.number("radius"));
    r.period = positive(s, "period", s.number("period"));
  } else if (r.type == "spline") {
    const YAML::Node points = s.required("waypoints");
    if (!points.IsSequence() || points.size() < 2)
      fail(s.file(), points, s.key("waypoints"), "expected a list of at least 2 points [x, y], got " + describe(points));
    for (size_t i = 0; i < points.size(); ++i) {
      const std::vector<double> p = s.toNumbers(points[i], s.key("waypoints") + "[" + std::to_string(i) + "]", 2);
      r.waypoints.emplace_back(p[0], p[1]);
      // A step far below the others makes the spline's knot spacing underflow or its
      // curvature overflow; a millimetre is far below any robot's reference.
      if (i > 0 && !((r.waypoints[i] - r.waypoints[i - 1]).norm() >= kMinWaypointStep))
        fail(s.file(), points[i], s.key("waypoints") + "[" + std::to_string(i) + "]",
             "within 1 mm of the previous waypoint (a spline needs distinct consecutive points)");
    }
    r.duration = positive(s, "duration", s.number("duration"));
  } else {
    fail(s.file(), s.node()["type"], s.key("type"), "unknown reference type '" + r.type + "' (rose, circle, spline)");
  }
  s.finish();
  return r;
}

void parseObstacles(const YAML::Node& list, const std::string& file, sim::ClosedLoopSetup& setup) {
  if (!list.IsSequence()) fail(file, list, "obstacles", "expected a list of {center, radius}, got " + describe(list));
  bool moving = false;
  std::vector<Eigen::Vector2d> velocities;
  for (size_t i = 0; i < list.size(); ++i) {
    Section s(list[i], "obstacles[" + std::to_string(i) + "]", file);
    core::Disk d;
    d.center = s.point("center");
    d.radius = positive(s, "radius", s.number("radius"));
    Eigen::Vector2d v = Eigen::Vector2d::Zero();
    if (s.has("velocity")) {
      const std::vector<double> xy = s.toNumbers(s.optional("velocity"), s.key("velocity"), 2);
      v = {xy[0], xy[1]};
      moving = true;
    } else {
      s.optional("velocity");
    }
    s.finish();
    setup.obstacles.push_back(d);
    velocities.push_back(v);
  }
  if (moving) setup.obstacle_velocities = velocities;
}

void parseSimulation(Section s, Scenario& scenario) {
  sim::ClosedLoopSetup& setup = scenario.setup;
  readScenarioFields(s, "simulation", scenario);
  const double seed = s.number("seed", 1.0);
  if (!(seed >= 0.0 && seed <= 9.0e15 && seed == std::floor(seed)))
    fail(s.file(), s.node()["seed"], s.key("seed"), "must be a whole number >= 0");
  setup.sensor.seed = static_cast<std::uint64_t>(seed);
  const sim::StepPolicy& policy = setup.step_policy;
  if (!(policy.comfortable_ratio < policy.tight_ratio))
    fail(s.file(), s.node()["comfortable_ratio"], s.key("comfortable_ratio"), "must be >= 0 and < tight_ratio");
  if (s.has("integrator")) {
    try {
      setup.integrator = parseIntegrator(s.text("integrator"));
    } catch (const std::invalid_argument& e) {
      fail(s.file(), s.node()["integrator"], s.key("integrator"), e.what());
    }
  } else {
    s.optional("integrator");
  }
  s.finish();
}

void parseTarget(Section s, Scenario& scenario) {
  sim::ClosedLoopSetup& setup = scenario.setup;
  readScenarioFields(s, "target", scenario);
  const YAML::Node jumps = s.optional("jumps");
  if (jumps.IsDefined() && !jumps.IsNull()) {
    if (!jumps.IsSequence()) fail(s.file(), jumps, s.key("jumps"), "expected a list of {t, offset}, got " + describe(jumps));
    for (size_t i = 0; i < jumps.size(); ++i) {
      Section j(jumps[i], s.key("jumps") + "[" + std::to_string(i) + "]", s.file());
      sim::TargetJump jump;
      jump.t = j.number("t");
      jump.offset = j.point("offset");
      j.finish();
      setup.sensor.jumps.push_back(jump);
    }
  }
  s.finish();
}

void parseLocalization(Section s, Scenario& scenario) {
  readScenarioFields(s, "localization", scenario);
  s.finish();
}

std::string stem(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = base.find_last_of('.');
  return dot == std::string::npos ? base : base.substr(0, dot);
}

}  // namespace

std::unique_ptr<core::Reference> Scenario::makeReference() const {
  const ReferenceSpec& r = reference;
  if (r.type == "rose") return std::make_unique<core::RoseReference>(r.amplitude, r.k, r.time_scale);
  if (r.type == "circle") return std::make_unique<core::CircleReference>(r.center, r.radius, r.period);
  return std::make_unique<core::SplineReference>(r.waypoints, r.duration);
}


Scenario parseScenario(const std::string& text, const std::string& file, const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ScenarioError(file + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
  }
  if (const auto big = core::yamlSizeProblem(root)) fail(file, big->node, "(document)", big->reason);
  for (const std::string& o : overrides) applyOverride(&root, file, o);
  Scenario scenario;
  scenario.file = file;
  scenario.name = stem(file);
  Section top(root, "", file);
  parseRobot(Section(top.required("robot"), "robot", file), scenario);
  parseController(Section(top.required("controller"), "controller", file), scenario.setup);
  scenario.reference = parseReference(Section(top.required("reference"), "reference", file));
  const YAML::Node obstacles = top.optional("obstacles");
  if (!obstacles.IsDefined()) fail(file, root, "obstacles", "missing (required; [] for none)");
  if (!obstacles.IsNull()) parseObstacles(obstacles, file, scenario.setup);
  parseSimulation(Section(top.required("simulation"), "simulation", file), scenario);
  if (top.has("target")) parseTarget(Section(top.optional("target"), "target", file), scenario);
  else top.optional("target");
  if (top.has("localization")) parseLocalization(Section(top.optional("localization"), "localization", file), scenario);
  else top.optional("localization");
  top.finish();
  checkScenario(scenario);
  return scenario;
}

Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  std::string text;
  try {
    text = core::readInputFile(path);
  } catch (const std::runtime_error& e) {
    throw ScenarioError(std::string(e.what()) + " (the scenario file)");
  }
  return parseScenario(text, path, overrides);
}

}  // namespace sim
}  // namespace amigobot_tracking
