#include "amigobot_tracking/core/perception/body_intrusion.h"

#include <sstream>

namespace amigobot_tracking {
namespace core {

std::string bodyIntrusion(const Eigen::Vector2d& centre, double body_radius, const std::vector<Disk>& laser_disks,
                          const std::vector<VirtualObstacle>& virtuals) {
  std::ostringstream why;
  why.precision(3);
  why << std::fixed;
  for (const Disk& disk : laser_disks) {
    const double d = (disk.center - centre).norm();
    if (d < body_radius) {
      why << "laser obstacle " << d << " m from the centre (body radius " << body_radius << " m)";
      return why.str();
    }
  }
  for (const VirtualObstacle& o : virtuals) {
    if ((o.disk.center - centre).norm() < o.disk.radius) {
      why << "virtual obstacle '" << o.id << "' (radius " << o.disk.radius << " m) contains the robot";
      return why.str();
    }
  }
  return "";
}

}  // namespace core
}  // namespace amigobot_tracking
