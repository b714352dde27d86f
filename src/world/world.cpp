#include "amigobot_tracking/world/world.h"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/core/support/input_file.h"

namespace amigobot_tracking {
namespace world {
namespace {

constexpr double kMinLength = 1e-6;  // [m] shorter segments or edges are degenerate
constexpr double kMinArea = 1e-9;    // [m^2]

// What is wrong with one shape: the sub-key ("" for the shape itself) and why; ok() when nothing.
struct Problem {
  std::string key, reason;
  bool ok() const { return reason.empty(); }
  // "list[i]" or "list[i].key"
  std::string where(const std::string& entry) const { return key.empty() ? entry : entry + "." + key; }
};

Problem diskProblem(const core::Disk& d) {
  if (!d.center.allFinite()) return {"center", "expected [x, y] in metres"};
  if (!(d.radius > 0.0) || !std::isfinite(d.radius)) return {"radius", "expected a radius > 0 in metres"};
  return {};
}

Problem personProblem(const Person& p) {
  if (!(p.radius > 0.0) || !std::isfinite(p.radius)) return {"radius", "expected a radius > 0 in metres"};
  const std::string bad = p.motion.validate();  // "key: reason"
  if (!bad.empty()) {
    const auto colon = bad.find(": ");
    return {bad.substr(0, colon), colon == std::string::npos ? bad : bad.substr(colon + 2)};
  }
  return {};
}

Problem segmentProblem(const Segment& s) {
  if (!s.from.allFinite() || !s.to.allFinite()) return {"", "expected finite [x, y] end points in metres"};
  if ((s.to - s.from).norm() < kMinLength) return {"", "degenerate segment: its two end points coincide"};
  return {};
}

Problem polygonProblem(const Polygon& p) {
  if (p.points.size() < 3) return {"points", "a polygon needs at least 3 points"};
  double twice_area = 0.0;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const Eigen::Vector2d& a = p.points[i];
    const Eigen::Vector2d& b = p.points[(i + 1) % p.points.size()];
    const std::string key = "points[" + std::to_string(i) + "]";
    if (!a.allFinite()) return {key, "expected finite [x, y] in metres"};
    if ((b - a).norm() < kMinLength) return {key, "repeats the next point"};
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  if (std::abs(twice_area) < 2.0 * kMinArea) return {"points", "degenerate polygon (no area)"};
  return {};
}

[[noreturn]] void fail(const std::string& path, const YAML::Node& node, const std::string& key,
                       const std::string& what) {
  const int line = node.IsDefined() ? node.Mark().line : -1;
  throw std::runtime_error(path + (line >= 0 ? ":" + std::to_string(line + 1) : "") + ": " + key + ": " + what);
}

// Refuses keys of `map` outside `known` (a misspelt key must not be ignored).
void onlyKeys(const std::string& path, const YAML::Node& map, const std::string& where,
              const std::set<std::string>& known) {
  for (const auto& item : map) {
    if (!item.first.IsScalar()) fail(path, item.first, where + "(key)", "a key must be a word, not a list or mapping");
    const std::string name = item.first.Scalar();
    if (!known.count(name)) fail(path, item.first, where + name, "unknown key (misspelt?)");
  }
}

// A flow list of `n` finite numbers, else nullopt.
std::optional<std::vector<double>> numbers(const YAML::Node& node, std::size_t n) {
  if (!node.IsSequence() || node.size() != n) return std::nullopt;
  std::vector<double> values;
  for (const YAML::Node& item : node) {
    double v = 0.0;
    if (!YAML::convert<double>::decode(item, v) || !std::isfinite(v)) return std::nullopt;
    values.push_back(v);
  }
  return values;
}

Eigen::Vector2d readPoint(const std::string& path, const YAML::Node& node, const std::string& key,
                          const char* expected = "expected [x, y] in metres (finite)") {
  const auto v = numbers(node, 2);
  if (!v) fail(path, node, key, expected);
  return {(*v)[0], (*v)[1]};
}

std::vector<Eigen::Vector2d> readPoints(const std::string& path, const YAML::Node& node, const std::string& key) {
  if (!node.IsSequence()) fail(path, node, key, "expected a list of [x, y] in metres");
  std::vector<Eigen::Vector2d> points;
  for (std::size_t i = 0; i < node.size(); ++i) {
    points.push_back(readPoint(path, node[i], key + "[" + std::to_string(i) + "]"));
  }
  return points;
}

core::Disk readDisk(const std::string& path, const YAML::Node& node, const std::string& key) {
  if (!node.IsMap()) fail(path, node, key, "expected {center: [x, y], radius: r > 0}");
  onlyKeys(path, node, key + ".", {"center", "radius"});
  const auto center = numbers(node["center"], 2);
  if (!center) fail(path, node, key + ".center", "expected [x, y] in metres");
  double radius = 0.0;
  if (!node["radius"] || !YAML::convert<double>::decode(node["radius"], radius) || !(radius > 0.0) ||
      !std::isfinite(radius)) {
    fail(path, node, key + ".radius", "expected a radius > 0 in metres");
  }
  return {{(*center)[0], (*center)[1]}, radius};
}

// A finite number at node[key] (default when absent), else a failure naming where.
double readNumber(const std::string& path, const YAML::Node& node, const std::string& key, const std::string& where,
                  double fallback, const char* expected) {
  if (!node[key]) return fallback;
  double v = 0.0;
  if (!YAML::convert<double>::decode(node[key], v) || !std::isfinite(v)) fail(path, node[key], where + key, expected);
  return v;
}

// One person: {radius, start, start_time, legs: [{duration, velocity}], repeat}.
Person readPerson(const std::string& path, const YAML::Node& node, const std::string& key) {
  const char* expected = "expected {radius: r, start: [x, y], start_time: s, legs: [{duration: s, velocity: [vx, vy]}], repeat: false}";
  if (!node.IsMap()) fail(path, node, key, expected);
  onlyKeys(path, node, key + ".", {"radius", "start", "start_time", "legs", "repeat"});
  Person person;
  if (!node["radius"]) fail(path, node, key + ".radius", "missing: a radius > 0 in metres");
  person.radius = readNumber(path, node, "radius", key + ".", 0.0, "expected a radius > 0 in metres");
  if (!node["start"]) fail(path, node, key + ".start", "missing: where it stands first, [x, y] in metres");
  person.motion.start = readPoint(path, node["start"], key + ".start");
  person.motion.start_time = readNumber(path, node, "start_time", key + ".", 0.0, "expected seconds on the emulator's clock");
  if (const YAML::Node repeat = node["repeat"]) {
    if (!repeat.IsScalar() || !YAML::convert<bool>::decode(repeat, person.motion.repeat)) {
      fail(path, repeat, key + ".repeat", "expected true or false");
    }
  }
  if (const YAML::Node legs = node["legs"]) {
    if (!legs.IsSequence()) fail(path, legs, key + ".legs", "expected a list of {duration: s, velocity: [vx, vy]}");
    for (std::size_t i = 0; i < legs.size(); ++i) {
      const std::string leg_key = key + ".legs[" + std::to_string(i) + "]";
      if (!legs[i].IsMap()) fail(path, legs[i], leg_key, "expected {duration: s > 0, velocity: [vx, vy] m/s}");
      onlyKeys(path, legs[i], leg_key + ".", {"duration", "velocity"});
      core::MotionLeg leg;
      leg.duration = readNumber(path, legs[i], "duration", leg_key + ".", 0.0, "expected a duration > 0 in seconds");
      if (!legs[i]["velocity"]) fail(path, legs[i], leg_key + ".velocity", "missing: [vx, vy] in m/s");
      leg.velocity = readPoint(path, legs[i]["velocity"], leg_key + ".velocity", "expected [vx, vy] in m/s (finite)");
      person.motion.legs.push_back(leg);
    }
  }
  const Problem problem = personProblem(person);
  if (!problem.ok()) fail(path, node, problem.where(key), problem.reason);
  return person;
}

// One wall entry: a segment {from, to} or an open chain {points}, appended as segments.
void readWall(const std::string& path, const YAML::Node& node, const std::string& key, std::vector<Segment>* walls) {
  const char* expected = "expected {from: [x, y], to: [x, y]} or {points: [[x, y], ...]}";
  if (!node.IsMap()) fail(path, node, key, expected);
  onlyKeys(path, node, key + ".", {"from", "to", "points"});
  std::vector<Eigen::Vector2d> chain;
  if (node["points"]) {
    if (node["from"] || node["to"]) fail(path, node, key, "either from/to or points, not both");
    chain = readPoints(path, node["points"], key + ".points");
    if (chain.size() < 2) fail(path, node, key + ".points", "a wall needs at least 2 points");
  } else {
    if (!node["from"] || !node["to"]) fail(path, node, key, expected);
    chain = {readPoint(path, node["from"], key + ".from"), readPoint(path, node["to"], key + ".to")};
  }
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const Segment s{chain[i], chain[i + 1]};
    const Problem problem = segmentProblem(s);
    if (!problem.ok()) fail(path, node, node["points"] ? key + ".points[" + std::to_string(i) + "]" : key, problem.reason);
    walls->push_back(s);
  }
}

Polygon readPolygon(const std::string& path, const YAML::Node& node, const std::string& key) {
  if (!node.IsMap()) fail(path, node, key, "expected {points: [[x, y], [x, y], [x, y], ...]}");
  onlyKeys(path, node, key + ".", {"points"});
  if (!node["points"]) fail(path, node, key + ".points", "missing: a list of at least 3 [x, y]");
  Polygon polygon{readPoints(path, node["points"], key + ".points")};
  const Problem problem = polygonProblem(polygon);
  if (!problem.ok()) fail(path, node, problem.where(key), problem.reason);
  return polygon;
}

// Calls read(node[i], "name[i]") for each entry of the list `name`, if present.
template <class Read>
void forEntries(const std::string& path, const YAML::Node& root, const std::string& name, const char* expected,
                Read read) {
  const YAML::Node list = root[name];
  if (!list) return;
  if (!list.IsSequence()) fail(path, list, name, std::string("expected a list of ") + expected);
  for (std::size_t i = 0; i < list.size(); ++i) read(list[i], name + "[" + std::to_string(i) + "]");
}

// The file's tree, refused when its aliases expand past core::kMaxYamlNodes (a loader
// walking them would build the expansion).
YAML::Node parseText(const std::string& text, const std::string& path) {
  const YAML::Node root = YAML::Load(text);  // its exceptions: parseWorld names the file
  if (const auto big = core::yamlSizeProblem(root)) fail(path, big->node, "(document)", big->reason);
  return root;
}

}  // namespace

namespace {
World parseWorldTree(const YAML::Node& root, const std::string& path);
}  // namespace

World loadWorld(const std::string& path) { return parseWorld(core::readInputFile(path), path); }

World parseWorld(const std::string& text, const std::string& path) {
  try {
    return parseWorldTree(parseText(text, path), path);
  } catch (const YAML::Exception& e) {  // yaml-cpp's own (an invalid node) must name the file too
    const std::string line = e.mark.is_null() ? "" : ":" + std::to_string(e.mark.line + 1);
    throw std::runtime_error(path + line + ": cannot read world: " + e.msg);
  }
}

namespace {

World parseWorldTree(const YAML::Node& root, const std::string& path) {
  if (!root.IsMap()) fail(path, root, "(top level)", "expected a mapping {initial_pose: ..., obstacles: [...], walls: [...]}");
  onlyKeys(path, root, "", {"initial_pose", "obstacles", "walls", "polygons", "people"});
  World world;
  if (const YAML::Node pose = root["initial_pose"]) {
    const auto v = numbers(pose, 3);
    if (!v) fail(path, pose, "initial_pose", "expected [x, y, theta] in m, m, rad");
    world.initial_pose = core::Pose2{(*v)[0], (*v)[1], (*v)[2]};
  }
  forEntries(path, root, "obstacles", "{center: [x, y], radius: r}", [&](const YAML::Node& n, const std::string& k) {
    world.obstacles.push_back(readDisk(path, n, k));
  });
  forEntries(path, root, "walls", "{from: [x, y], to: [x, y]} or {points: [[x, y], ...]}",
             [&](const YAML::Node& n, const std::string& k) { readWall(path, n, k, &world.walls); });
  forEntries(path, root, "polygons", "{points: [[x, y], ...]}", [&](const YAML::Node& n, const std::string& k) {
    world.polygons.push_back(readPolygon(path, n, k));
  });
  forEntries(path, root, "people", "{radius: r, start: [x, y], legs: [...]}", [&](const YAML::Node& n, const std::string& k) {
    world.people.push_back(readPerson(path, n, k));
  });
  return world;
}

}  // namespace

std::string worldYaml(const World& world) {
  std::ostringstream out;
  out.precision(17);
  const auto point = [&out](const Eigen::Vector2d& p) { out << "[" << p.x() << ", " << p.y() << "]"; };
  if (world.initial_pose) {
    out << "initial_pose: [" << world.initial_pose->x << ", " << world.initial_pose->y << ", "
        << world.initial_pose->theta << "]\n";
  }
  if (!world.obstacles.empty()) out << "obstacles:\n";
  for (const core::Disk& d : world.obstacles) {
    out << "  - {center: ";
    point(d.center);
    out << ", radius: " << d.radius << "}\n";
  }
  if (!world.walls.empty()) out << "walls:\n";
  for (const Segment& s : world.walls) {
    out << "  - {from: ";
    point(s.from);
    out << ", to: ";
    point(s.to);
    out << "}\n";
  }
  if (!world.polygons.empty()) out << "polygons:\n";
  for (const Polygon& p : world.polygons) {
    out << "  - {points: [";
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      if (i > 0) out << ", ";
      point(p.points[i]);
    }
    out << "]}\n";
  }
  if (!world.people.empty()) out << "people:\n";
  for (const Person& p : world.people) {
    out << "  - {radius: " << p.radius << ", start: ";
    point(p.motion.start);
    out << ", start_time: " << p.motion.start_time << ", repeat: " << (p.motion.repeat ? "true" : "false") << ", legs: [";
    for (std::size_t i = 0; i < p.motion.legs.size(); ++i) {
      out << (i > 0 ? ", " : "") << "{duration: " << p.motion.legs[i].duration << ", velocity: ";
      point(p.motion.legs[i].velocity);
      out << "}";
    }
    out << "]}\n";
  }
  return world.empty() && !world.initial_pose ? "{}\n" : out.str();
}

World worldAt(const World& world, double t) {
  World now = world;
  now.people.clear();
  for (const Person& p : world.people) now.obstacles.push_back(p.diskAt(t));
  return now;
}

std::string validateWorld(const World& world) {
  // The first problem of the shapes of `list`, as "list[i].key: reason".
  const auto first = [](const char* list, const auto& shapes, auto check) -> std::string {
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      const Problem p = check(shapes[i]);
      if (!p.ok()) return p.where(std::string(list) + "[" + std::to_string(i) + "]") + ": " + p.reason;
    }
    return "";
  };
  std::string bad = first("obstacles", world.obstacles, diskProblem);
  if (bad.empty()) bad = first("walls", world.walls, segmentProblem);
  if (bad.empty()) bad = first("polygons", world.polygons, polygonProblem);
  if (bad.empty()) bad = first("people", world.people, personProblem);
  if (bad.empty() && world.initial_pose && !world.initial_pose->isFinite()) bad = "initial_pose: must be finite";
  return bad;
}

}  // namespace world
}  // namespace amigobot_tracking
