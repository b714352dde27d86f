#include "amigobot_tracking/sensors/scan_source.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "amigobot_tracking/sensors/laser_protocol.h"
#include "amigobot_tracking/world/raycast.h"

namespace amigobot_tracking {
namespace sensors {

void ScanSourceOptions::validate() const {
  if (!mount.isFinite()) throw std::invalid_argument("mount pose: must be finite");
  if (!(range_noise >= 0.0 && range_noise < 1.0)) throw std::invalid_argument("range_noise: must be within [0, 1) m");
  if (!(dropout >= 0.0 && dropout <= 1.0)) throw std::invalid_argument("dropout: must be within [0, 1]");
}

ScanSource::ScanSource(LaserModel model, world::World world, ScanSourceOptions options)
    : model_(std::move(model)), world_(std::move(world)), options_(options), random_(options.seed) {
  options_.validate();
}

core::Pose2 ScanSource::sensorPose(const core::Pose2& base) const {
  const double c = std::cos(base.theta), s = std::sin(base.theta);
  core::Pose2 sensor;
  sensor.x = base.x + c * options_.mount.x - s * options_.mount.y;
  sensor.y = base.y + s * options_.mount.x + c * options_.mount.y;
  sensor.theta = base.theta + options_.mount.theta;
  return sensor;
}

std::vector<float> ScanSource::revolution(const core::Pose2& sensor, const world::World& room, const core::ScanGeometry& grid,
                                          std::vector<float>* angles) {
  // The protocol says where this revolution's samples fall (they vary from one to the next).
  std::vector<float> ranges;
  for (const double angle : protocolOf(model_).revolutionAngles(model_, &phase_, random_)) {
    core::ScanGeometry beam = grid;
    beam.angle_min = options_.upside_down ? -angle : angle;  // looks at -angle in the mount frame
    angles->push_back(static_cast<float>(angle));
    ranges.push_back(world::raycastScan(sensor, room, beam, 1)[0]);
  }
  return ranges;
}

EmulatedScan ScanSource::cast(const core::Pose2& base, double t) {
  // People (moving disks) stand where they are at t, the emulator's clock of the pose.
  if (!world_.people.empty()) snapshot_ = world::worldAt(world_, t);
  const world::World& room = world_.people.empty() ? world_ : snapshot_;
  core::ScanGeometry geometry = model_.geometry();
  if (options_.upside_down) {  // beam i looks at -angle_i in the mount frame
    geometry.angle_min = -geometry.angle_min;
    geometry.angle_increment = -geometry.angle_increment;
  }
  EmulatedScan scan;
  if (protocolOf(model_).samplesAsItTurns()) {
    scan.ranges = revolution(sensorPose(base), room, geometry, &scan.angles);
  } else {
    scan.ranges = world::raycastScan(sensorPose(base), room, geometry, model_.beams());
  }
  scan.t = t;
  scan.index = index_++;
  std::normal_distribution<double> noise(0.0, options_.range_noise);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (float& r : scan.ranges) {
    if (options_.dropout > 0.0 && uniform(random_) < options_.dropout) {
      r = std::numeric_limits<float>::quiet_NaN();
    } else if (std::isfinite(r) && options_.range_noise > 0.0) {
      r = static_cast<float>(std::max(model_.range_min, std::min(model_.range_max, r + noise(random_))));
    }
  }
  return scan;
}

}  // namespace sensors
}  // namespace amigobot_tracking
