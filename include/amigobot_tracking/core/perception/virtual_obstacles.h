// Virtual obstacles: disks in the global frame that an operator adds (YAML list at start,
// topic, rviz click, interactive marker) and that stay until removed. Pure bookkeeping,
// Eigen only; the controller treats them exactly like detected obstacles.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

struct VirtualObstacle {
  std::string id;  // unique, non-empty
  Disk disk;       // centre [m] in the global frame, radius [m] > 0
};

// Empty when the obstacle is usable, otherwise a reason naming the field.
std::string validateVirtualObstacle(const VirtualObstacle& obstacle);

class VirtualObstacleSet {
 public:
  enum class Change { kAdded, kUpdated, kRejected };

  // Adds the obstacle, or replaces the one with the same id (keeping its place in the
  // order). Invalid obstacles are rejected and change nothing; *why says why.
  Change upsert(const VirtualObstacle& obstacle, std::string* why = nullptr);
  // Removes the obstacle with this id; false when there is none.
  bool remove(const std::string& id);
  void clear();
  // Replaces the whole set by a list (e.g. the YAML list at start). All-or-nothing: on the
  // first invalid or duplicate entry nothing changes and *why names the entry by index.
  bool assign(const std::vector<VirtualObstacle>& list, std::string* why = nullptr);

  const VirtualObstacle* find(const std::string& id) const;
  const std::vector<VirtualObstacle>& all() const { return obstacles_; }
  std::size_t size() const { return obstacles_.size(); }
  bool empty() const { return obstacles_.empty(); }
  // Appends the disks to *out (for the controller's obstacle list).
  void appendDisks(std::vector<Disk>* out) const;
  // An id not in use, "<prefix><n>" with n counting up (for clicked points).
  std::string freshId(const std::string& prefix);
  // Increases on every change: publishers republish when it moved.
  std::uint64_t version() const { return version_; }

 private:
  std::vector<VirtualObstacle> obstacles_;  // insertion order; a handful, linear search
  std::uint64_t version_ = 0;
  std::uint64_t next_serial_ = 1;
};

}  // namespace core
}  // namespace amigobot_tracking
