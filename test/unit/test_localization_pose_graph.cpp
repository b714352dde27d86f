// The pose graph (Gauss-Newton) and the trajectory errors that score the mapping: a loop of
// poses whose odometry drifts is pulled back onto the truth by one loop edge; a wrong loop
// edge pulls with bounded force when robust; ATE ignores where the estimate's frame is.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "amigobot_tracking/localization/pose_graph.h"
#include "amigobot_tracking/localization/poses.h"
#include "amigobot_tracking/localization/trajectory_error.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::localization;

namespace {

// 20 poses round a 4 m x 4 m square (5 per side, turning at the corners).
std::vector<core::Pose2> square() {
  std::vector<core::Pose2> poses;
  core::Pose2 p;
  for (int i = 0; i < 20; ++i) {
    poses.push_back(p);
    p = compose(p, core::Pose2{0.8, 0.0, (i % 5 == 4) ? M_PI / 2 : 0.0});
  }
  return poses;
}

Eigen::Matrix3d information() { return Eigen::Vector3d(400.0, 400.0, 2500.0).asDiagonal(); }

// The graph of the square: odometry edges that over-turn 0.03 rad per step, initial poses
// chained from them, and (optionally) the loop edge from the last pose back to the first.
PoseGraph driftingSquare(bool loop, const core::Pose2& loop_error = core::Pose2(), bool robust = false) {
  const std::vector<core::Pose2> truth = square();
  PoseGraph graph;
  core::Pose2 guess = truth[0];
  graph.addNode(guess);
  for (std::size_t i = 1; i < truth.size(); ++i) {
    core::Pose2 step = compose(inverse(truth[i - 1]), truth[i]);
    step.theta += 0.03;
    guess = compose(guess, step);
    graph.addNode(guess);
    graph.addEdge({static_cast<int>(i) - 1, static_cast<int>(i), step, information(), false});
  }
  if (loop) graph.addEdge({19, 0, compose(compose(inverse(truth[19]), truth[0]), loop_error), information(), robust});
  return graph;
}

double worstError(const PoseGraph& graph) {
  const std::vector<core::Pose2> truth = square();
  double worst = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i)
    worst = std::max(worst, std::hypot(graph.nodes()[i].x - truth[i].x, graph.nodes()[i].y - truth[i].y));
  return worst;
}

}  // namespace

TEST(PoseGraph, OneLoopEdgePullsADriftingSquareBackOntoTheTruth) {
  PoseGraph open = driftingSquare(false);
  PoseGraph closed = driftingSquare(true);
  ASSERT_GT(worstError(closed), 1.0);  // the drift before optimising
  const double before = closed.error();
  const double after = closed.optimize(20);
  EXPECT_LT(after, 0.05 * before);
  // The odometry edges over-turn, so the loop spreads their heading error over the square: it
  // comes back to within centimetres; without the loop nothing moves (the chain is consistent).
  EXPECT_LT(worstError(closed), 0.1);
  open.optimize(20);
  EXPECT_GT(worstError(open), 1.0);
  EXPECT_NEAR(closed.nodes()[0].x, 0.0, 1e-6);  // node 0 holds the map frame
}

TEST(PoseGraph, AWrongRobustLoopEdgeMovesTheMapLessThanAPlainOne) {
  PoseGraph robust = driftingSquare(true, core::Pose2{2.0, 0.0, 0.0}, true);
  robust.optimize(30);
  PoseGraph plain = driftingSquare(true, core::Pose2{2.0, 0.0, 0.0});
  PoseGraphEdge wrong = plain.edges().back();
  // The same wrong loop edge without the Huber weight, in a fresh graph.
  PoseGraph unweighted;
  for (const core::Pose2& p : plain.nodes()) unweighted.addNode(p);
  for (std::size_t i = 0; i + 1 < plain.edges().size(); ++i) unweighted.addEdge(plain.edges()[i]);
  wrong.robust = false;
  unweighted.addEdge(wrong);
  unweighted.optimize(30);
  const core::Pose2 end_robust = robust.nodes().back(), end_plain = unweighted.nodes().back();
  const core::Pose2 odometry_end = driftingSquare(false).nodes().back();
  EXPECT_LT(std::hypot(end_robust.x - odometry_end.x, end_robust.y - odometry_end.y),
            std::hypot(end_plain.x - odometry_end.x, end_plain.y - odometry_end.y));
}

TEST(PoseGraph, RefusesAnEdgeToAMissingNode) {
  PoseGraph graph;
  graph.addNode(core::Pose2());
  EXPECT_THROW(graph.addEdge({0, 1, core::Pose2(), information(), false}), std::invalid_argument);
  EXPECT_THROW(graph.addEdge({0, 0, core::Pose2(), information(), false}), std::invalid_argument);
}

TEST(TrajectoryError, AteIgnoresTheEstimatesFrameAndMeasuresWhatRemains) {
  const std::vector<core::Pose2> truth = square();
  std::vector<core::Pose2> moved, bent;
  const core::Pose2 frame{3.0, -2.0, 0.7};
  for (const core::Pose2& p : truth) moved.push_back(compose(frame, p));
  const AbsoluteError same = absoluteError(moved, truth);
  EXPECT_LT(same.rms, 1e-9);
  EXPECT_LT(same.heading_rms, 1e-9);
  bent = truth;
  bent[7].x += 0.5;  // one pose off by 0.5 m: max just under 0.5 (the alignment shares it)
  const AbsoluteError one = absoluteError(bent, truth);
  EXPECT_NEAR(one.max, 0.5, 0.05);
  EXPECT_GT(one.rms, 0.1);
  EXPECT_THROW(absoluteError(truth, std::vector<core::Pose2>(3)), std::invalid_argument);
}

TEST(TrajectoryError, RelativeErrorIsTheMotionErrorPerRelation) {
  const std::vector<core::Pose2> truth = square();
  std::vector<core::Pose2> long_steps;
  core::Pose2 p;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    long_steps.push_back(p);
    if (i + 1 < truth.size()) {
      core::Pose2 step = compose(inverse(truth[i]), truth[i + 1]);
      step.x *= 1.1;  // 8 cm too far per 0.8 m step
      p = compose(p, step);
    }
  }
  const RelativeError e = relativeError(long_steps, consecutiveRelations(truth));
  EXPECT_EQ(e.relations, 19);
  EXPECT_NEAR(e.translation_mean, 0.08, 1e-9);
  EXPECT_NEAR(e.translation_std, 0.0, 1e-9);
  EXPECT_NEAR(e.rotation_mean, 0.0, 1e-9);
}
