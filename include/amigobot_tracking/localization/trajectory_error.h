// How far an estimated trajectory is from a reference one, the two ways SLAM is scored:
// - the absolute trajectory error (ATE): position error per pose after the rigid motion that
//   best lays the estimate on the reference (Horn's closed form, planar), RMS and max;
// - the relative error of Kuemmerle et al. 2009 ("On measuring the accuracy of SLAM
//   algorithms", Auton. Robots 27): for relations (i, j), the motion from pose i to pose j as
//   estimated against the reference's, translation [m] and rotation [rad], mean and standard
//   deviation. Relations come from their published *.relations files (matched by timestamp) or,
//   without one, from consecutive reference poses.
#pragma once

#include <string>
#include <vector>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace localization {

struct AbsoluteError {
  double rms = 0.0, max = 0.0;  // [m]
  double heading_rms = 0.0;     // [rad]
  int poses = 0;
};

struct RelativeError {
  double translation_mean = 0.0, translation_std = 0.0;  // [m]
  double rotation_mean = 0.0, rotation_std = 0.0;        // [rad]
  int relations = 0;
};

// The reference motion from pose i to pose j (in i's frame).
struct Relation {
  int i = 0, j = 0;
  core::Pose2 motion;
};
using Relations = std::vector<Relation>;

// Throws std::invalid_argument when the trajectories differ in length or are empty.
AbsoluteError absoluteError(const std::vector<core::Pose2>& estimate, const std::vector<core::Pose2>& reference);
RelativeError relativeError(const std::vector<core::Pose2>& estimate, const Relations& relations);
// (0, 1), (1, 2), ... between consecutive reference poses.
Relations consecutiveRelations(const std::vector<core::Pose2>& reference);
// A relations file ("t1 t2 x y z roll pitch yaw" per line): each stamp matched to the pose
// whose stamp is within `tolerance` [s]; unmatched relations are left out. Throws
// std::runtime_error "FILE:LINE: ..." for a malformed line.
Relations readRelations(const std::string& path, const std::vector<double>& stamps, double tolerance = 1e-3);

}  // namespace localization
}  // namespace amigobot_tracking
