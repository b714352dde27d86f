// A planar pose graph and its least-squares solution by Gauss-Newton on Eigen's sparse
// Cholesky (the formulation of Grisetti et al., "A tutorial on graph-based SLAM", 2010): nodes
// are poses, an edge says where node `to` is seen from node `from` with an information matrix.
// Node 0 is held fixed (the map frame). Loop edges get a Huber weight, so one wrong loop pulls
// with a bounded force instead of tearing the map.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace localization {

struct PoseGraphEdge {
  int from = 0, to = 0;
  core::Pose2 measurement;  // pose of `to` in the frame of `from`
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
  bool robust = false;      // Huber-weighted (loop closures)
};

class PoseGraph {
 public:
  int addNode(const core::Pose2& pose);  // returns its index
  void addEdge(const PoseGraphEdge& edge);
  // Gauss-Newton until the step is below 1e-6 or `iterations` are done; returns the final
  // weighted squared error.
  double optimize(int iterations);
  double error() const;  // weighted squared error of the current poses

  const std::vector<core::Pose2>& nodes() const { return nodes_; }
  const std::vector<PoseGraphEdge>& edges() const { return edges_; }

 private:
  std::vector<core::Pose2> nodes_;
  std::vector<PoseGraphEdge> edges_;
};

}  // namespace localization
}  // namespace amigobot_tracking
