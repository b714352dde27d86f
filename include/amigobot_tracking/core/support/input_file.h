// Reading an input file (a config, a scenario, a world, a map and its image) defensively. Only
// a regular file up to a size cap is read, so `image: /dev/zero`, a FIFO or a directory is an
// error naming the file instead of a hang or memory growing until the process is killed. And
// the size of a parsed YAML tree with its aliases expanded: yaml-cpp shares an aliased node,
// but a loader walking the tree walks it once per alias, so a small file of nested aliases
// can make a loader build gigabytes (a 0.57 MB world file reached ~1 GB).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace amigobot_tracking {
namespace core {

constexpr std::uintmax_t kMaxConfigFileBytes = 4u << 20;  // YAML files: the shipped ones are < 5 kB
constexpr std::size_t kMaxYamlNodes = 1000000;             // with aliases expanded
constexpr int kMaxYamlDepth = 64;                          // the deepest shipped file nests 4

// "" when `path` names a regular file (after symbolic links) of at most max_bytes, else why
// not ("is a directory", "is not a regular file (a device, FIFO or socket)", "is 5 GB, more
// than ...", "does not exist").
std::string regularFileProblem(const std::string& path, std::uintmax_t max_bytes);

// The file's bytes. Throws std::runtime_error "PATH: reason" when regularFileProblem has one,
// when it cannot be read, or when it grew past max_bytes while being read.
std::string readInputFile(const std::string& path, std::uintmax_t max_bytes = kMaxConfigFileBytes);

// Where a YAML tree is too large and why.
template <class Node>
struct YamlSizeProblem {
  Node node;  // the node at which the count passed the limit (its Mark() gives the line)
  std::string reason;
};

// The first node at which the tree rooted at `root`, aliases expanded, exceeds max_nodes
// nodes or max_depth levels (a cycle exceeds both), else nullopt. Node is YAML::Node; a
// template so that core stays free of yaml-cpp (the layers that read YAML instantiate it).
// Stops at the limit, so its time is bounded by max_nodes whatever the aliases.
template <class Node>
std::optional<YamlSizeProblem<Node>> yamlSizeProblem(const Node& root, std::size_t max_nodes = kMaxYamlNodes,
                                                     int max_depth = kMaxYamlDepth) {
  std::size_t seen = 0;
  std::optional<YamlSizeProblem<Node>> problem;
  const auto visit = [&](const Node& node, int depth, const auto& self) -> bool {
    if (++seen > max_nodes) {
      problem = YamlSizeProblem<Node>{node, "more than " + std::to_string(max_nodes) +
                                                " YAML nodes once aliases are expanded (nested aliases?)"};
    } else if (depth > max_depth) {
      problem = YamlSizeProblem<Node>{node, "nested more than " + std::to_string(max_depth) +
                                                " levels deep (a recursive alias?)"};
    } else if (node.IsMap()) {
      for (const auto& item : node)
        if (!self(item.first, depth + 1, self) || !self(item.second, depth + 1, self)) return false;
    } else if (node.IsSequence()) {
      for (const auto& item : node)
        if (!self(static_cast<const Node&>(item), depth + 1, self)) return false;
    }
    return !problem;
  };
  visit(root, 0, visit);
  return problem;
}

}  // namespace core
}  // namespace amigobot_tracking
