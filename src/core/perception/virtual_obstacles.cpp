#include "amigobot_tracking/core/perception/virtual_obstacles.h"

#include "amigobot_tracking/core/support/field_table.h"  // kMaxRadius

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace amigobot_tracking {
namespace core {

std::string validateVirtualObstacle(const VirtualObstacle& obstacle) {
  std::ostringstream err;
  if (obstacle.id.empty()) {
    err << "id must not be empty";
  } else if (!obstacle.disk.center.allFinite()) {
    err << "center of '" << obstacle.id << "' must be finite";
  } else if (!(obstacle.disk.radius > 0.0 && obstacle.disk.radius <= kMaxRadius)) {
    err << "radius of '" << obstacle.id << "' must be in (0, " << kMaxRadius << "] m, got " << obstacle.disk.radius;
  }
  return err.str();
}

VirtualObstacleSet::Change VirtualObstacleSet::upsert(const VirtualObstacle& obstacle, std::string* why) {
  const std::string error = validateVirtualObstacle(obstacle);
  if (!error.empty()) {
    if (why) *why = error;
    return Change::kRejected;
  }
  ++version_;
  for (VirtualObstacle& existing : obstacles_) {
    if (existing.id == obstacle.id) {
      existing.disk = obstacle.disk;
      return Change::kUpdated;
    }
  }
  obstacles_.push_back(obstacle);
  return Change::kAdded;
}

bool VirtualObstacleSet::remove(const std::string& id) {
  const auto it = std::find_if(obstacles_.begin(), obstacles_.end(),
                               [&](const VirtualObstacle& o) { return o.id == id; });
  if (it == obstacles_.end()) return false;
  obstacles_.erase(it);
  ++version_;
  return true;
}

void VirtualObstacleSet::clear() {
  obstacles_.clear();
  ++version_;
}

bool VirtualObstacleSet::assign(const std::vector<VirtualObstacle>& list, std::string* why) {
  std::set<std::string> ids;
  for (std::size_t i = 0; i < list.size(); ++i) {
    std::string error = validateVirtualObstacle(list[i]);
    if (error.empty() && !ids.insert(list[i].id).second) error = "id '" + list[i].id + "' appears twice";
    if (!error.empty()) {
      if (why) *why = "entry " + std::to_string(i) + ": " + error;
      return false;
    }
  }
  obstacles_ = list;
  ++version_;
  return true;
}

const VirtualObstacle* VirtualObstacleSet::find(const std::string& id) const {
  for (const VirtualObstacle& o : obstacles_) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

void VirtualObstacleSet::appendDisks(std::vector<Disk>* out) const {
  for (const VirtualObstacle& o : obstacles_) out->push_back(o.disk);
}

std::string VirtualObstacleSet::freshId(const std::string& prefix) {
  std::string id;
  do {
    id = prefix + std::to_string(next_serial_++);
  } while (find(id) != nullptr);
  return id;
}

}  // namespace core
}  // namespace amigobot_tracking
