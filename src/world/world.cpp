#include "amigobot_tracking/world/world.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

namespace amigobot_tracking {
namespace world {
namespace {

[[noreturn]] void fail(const std::string& path, const YAML::Node& node, const std::string& key,
                       const std::string& what) {
  const int line = node.Mark().line;
  throw std::runtime_error(path + (line >= 0 ? ":" + std::to_string(line + 1) : "") + ": " + key + ": " + what);
}

// Refuses keys of `map` outside `known` (a misspelt key must not be ignored).
void onlyKeys(const std::string& path, const YAML::Node& map, const std::string& where,
              const std::set<std::string>& known) {
  for (const auto& item : map) {
    const std::string name = item.first.as<std::string>();
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

YAML::Node parseFile(const std::string& path) {
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": cannot read world: " + e.what());
  }
}

}  // namespace

World loadWorld(const std::string& path) {
  const YAML::Node root = parseFile(path);
  if (!root.IsMap()) fail(path, root, "(top level)", "expected a mapping {initial_pose: ..., obstacles: [...]}");
  onlyKeys(path, root, "", {"initial_pose", "obstacles"});
  World world;
  if (const YAML::Node pose = root["initial_pose"]) {
    const auto v = numbers(pose, 3);
    if (!v) fail(path, pose, "initial_pose", "expected [x, y, theta] in m, m, rad");
    world.initial_pose = core::Pose2{(*v)[0], (*v)[1], (*v)[2]};
  }
  if (const YAML::Node obstacles = root["obstacles"]) {
    if (!obstacles.IsSequence()) fail(path, obstacles, "obstacles", "expected a list of {center: [x, y], radius: r}");
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      world.obstacles.push_back(readDisk(path, obstacles[i], "obstacles[" + std::to_string(i) + "]"));
    }
  }
  return world;
}

}  // namespace world
}  // namespace amigobot_tracking
