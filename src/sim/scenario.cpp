#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/robot_description.h"

#include <cmath>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/core/support/input_file.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/sim/scenario_fields.h"
#include "amigobot_tracking/sim/yaml_section.h"

namespace amigobot_tracking {
namespace sim {
namespace {

constexpr double kMinWaypointStep = 1e-3;  // [m]

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

void parseController(Section s, Scenario& scenario) {
  sim::ClosedLoopSetup& setup = scenario.setup;
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
  // rho = rho_inf, k_d / rho_inf (T(s) ~ s); the baseline rows (scenario_fields.cpp) keep it
  // unless the file gives k_p.
  setup.baseline.k_p = c.k_d / c.rho_inf;
  readScenarioFields(s, "controller", scenario);
  s.finish();
}

core::ReferenceSpec parseReference(Section s) {
  core::ReferenceSpec r;
  r.type = s.text("type");
  const core::ReferenceCurve* curve = nullptr;
  try {
    curve = &core::referenceCurve(r.type);
  } catch (const std::invalid_argument& e) {
    fail(s.file(), s.node()["type"], s.key("type"), e.what());
  }
  // The curve's own keys (core::referenceCurves()); another curve's key is left unread, so
  // finish() names it as unknown here.
  for (const std::string& key : curve->required) s.required(key);  // "missing (required)"
  readSection(s, core::referenceFields(), r, [&](const std::string& key) { return curve->takes(key) ? key : std::string(); });
  if (curve->center) r.center = s.point("center");
  if (curve->waypoints) {
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
  }
  // readSection held each key read to the table's bounds (those the factory holds every spec
  // to, e.g. radius <= 100 m), naming this file and key; the keys not read keep valid defaults.
  s.finish();
  return r;
}

// An obstacle's `motion`: when its legs begin, the legs (duration, velocity), whether they repeat.
core::ObstacleMotion parseMotion(Section s, const Eigen::Vector2d& start) {
  core::ObstacleMotion m;
  m.start = start;
  m.start_time = s.number("start_time", 0.0);
  m.repeat = s.boolean("repeat", false);
  const YAML::Node legs = s.required("legs");
  if (!legs.IsSequence() || legs.size() == 0)
    fail(s.file(), legs, s.key("legs"), "expected a list of {duration, velocity}, got " + describe(legs));
  for (size_t i = 0; i < legs.size(); ++i) {
    Section leg(legs[i], s.key("legs") + "[" + std::to_string(i) + "]", s.file());
    const double duration = positive(leg, "duration", leg.number("duration"));
    m.legs.push_back({duration, leg.point("velocity")});
    leg.finish();
  }
  const std::string why = m.validate();
  if (!why.empty()) fail(s.file(), s.node(), s.key(why.substr(0, why.find(':'))), why.substr(why.find(':') + 2));
  s.finish();
  return m;
}

void parseObstacles(const YAML::Node& list, const std::string& file, sim::ClosedLoopSetup& setup) {
  if (!list.IsSequence()) fail(file, list, "obstacles", "expected a list of {center, radius}, got " + describe(list));
  bool moving = false;
  std::vector<core::ObstacleMotion> motions;
  for (size_t i = 0; i < list.size(); ++i) {
    Section s(list[i], "obstacles[" + std::to_string(i) + "]", file);
    core::Disk d;
    d.center = s.point("center");
    d.radius = positive(s, "radius", s.number("radius"));
    // `velocity`: a constant velocity from the start; `motion`: legs of piecewise-constant
    // velocity (walk, stop, turn); neither: static. One description either way (ObstacleMotion).
    if (s.has("velocity") && s.has("motion"))
      fail(file, s.node()["motion"], s.key("motion"), "give velocity (constant) or motion (legs), not both");
    core::ObstacleMotion motion = constantMotion(d.center, Eigen::Vector2d::Zero());
    if (s.has("velocity")) {
      const std::vector<double> xy = s.toNumbers(s.optional("velocity"), s.key("velocity"), 2);
      motion = constantMotion(d.center, {xy[0], xy[1]});
      moving = true;
    } else if (s.has("motion")) {
      motion = parseMotion(Section(s.optional("motion"), s.key("motion"), file), d.center);
      moving = true;
    }
    s.optional("velocity");
    s.optional("motion");
    s.finish();
    setup.obstacles.push_back(d);
    motions.push_back(motion);
  }
  if (moving) setup.obstacle_motions = motions;
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
  return core::makeReference(reference);
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
  parseController(Section(top.required("controller"), "controller", file), scenario);
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
