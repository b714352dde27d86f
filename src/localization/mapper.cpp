#include "amigobot_tracking/localization/mapper.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>

#include "amigobot_tracking/localization/graph_mapper.h"
#include "amigobot_tracking/localization/map_drawing.h"
#include "amigobot_tracking/localization/poses.h"

namespace amigobot_tracking {
namespace localization {

Mapper::Mapper(const LocalizationConfig& config) : config_(config) {
  estimate_.pose = config.initial_pose;
  estimate_.covariance.setZero();  // until the first scan's
  if (config.mapping_method == "graph") {
    graph_ = std::make_unique<GraphMapper>(config);
    return;
  }
  builder_ = std::make_unique<mrpt::slam::CMetricMapBuilderICP>();
  builder_->setVerbosityLevel(mrpt::system::LVL_ERROR);
  auto& options = builder_->ICP_options;
  options.matchAgainstTheGrid = false;
  options.localizationLinDistance = config.min_travel;
  options.localizationAngDistance = config.min_rotation;
  // New points are inserted every few cells of travel: the point map stays small and fast.
  options.insertionLinDistance = std::max(config.min_travel, 4.0 * config.resolution);
  options.insertionAngDistance = std::max(config.min_rotation, 0.1);
  options.minICPgoodnessToAccept = 0.4;
  mrpt::maps::COccupancyGridMap2D::TMapDefinition grid;
  grid.resolution = static_cast<float>(config.resolution);
  grid.min_x = grid.min_y = -5.0f;  // grows as the scans reach farther
  grid.max_x = grid.max_y = 5.0f;
  grid.insertionOpts.maxDistanceInsertion = static_cast<float>(config.range_max);
  options.mapInitializers.push_back(grid);
  mrpt::maps::CSimplePointsMap::TMapDefinition points;
  points.insertionOpts.minDistBetweenLaserPoints = static_cast<float>(config.resolution);
  options.mapInitializers.push_back(points);
  auto& icp = builder_->ICP_params;
  icp.maxIterations = static_cast<unsigned>(config.icp.max_iterations);
  icp.thresholdDist = config.icp.max_correspondence;
  icp.smallestThresholdDist = config.icp.min_correspondence;
  icp.corresponding_points_decimation = 1;
  const mrpt::poses::CPosePDFGaussian start(toMrpt(config.initial_pose));
  builder_->initialize(mrpt::maps::CSimpleMap(), &start);
  clock_origin_ = mrpt::Clock::now();
}

Mapper::~Mapper() = default;

const PoseEstimate& Mapper::update(const RangeScan& scan, const core::Pose2& odom_base) {
  if (graph_) {
    graph_->update(scan, odom_base, &estimate_);
    return estimate_;
  }
  const core::Pose2 increment = estimate_.scans == 0 ? core::Pose2() : compose(inverse(last_odom_), odom_base);
  last_odom_ = odom_base;
  // MRPT wants increasing timestamps after its own clock at initialize(): the time since the
  // first scan (at least 1 ms more than the last) after that clock.
  if (estimate_.scans == 0) first_stamp_ = scan.stamp;
  elapsed_ = estimate_.scans == 0 ? 0.0 : std::max(scan.stamp - first_stamp_, elapsed_ + 1e-3);
  const mrpt::Clock::time_point stamp =
      clock_origin_ + std::chrono::duration_cast<mrpt::Clock::duration>(std::chrono::duration<double>(elapsed_ + 1e-3));
  mrpt::obs::CActionRobotMovement2D movement;
  movement.computeFromOdometry(toMrpt(increment), mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
  movement.timestamp = stamp;
  mrpt::obs::CActionCollection actions;
  actions.insert(movement);
  mrpt::obs::CSensoryFrame frame;
  const mrpt::obs::CObservation2DRangeScan::Ptr observation = toObservation(scan, config_.range_max);
  observation->timestamp = stamp;
  frame.insert(observation);
  builder_->processActionObservation(actions, frame);
  ++estimate_.scans;
  mrpt::poses::CPose3D mean;
  const mrpt::poses::CPose3DPDF::Ptr pdf = builder_->getCurrentPoseEstimation();
  pdf->getMean(mean);
  estimate_.pose = core::Pose2{mean.x(), mean.y(), mean.yaw()};
  estimate_.map_to_odom = compose(estimate_.pose, inverse(odom_base));
  const auto [cov, unused] = pdf->getCovarianceAndMean();
  (void)unused;
  estimate_.covariance << cov(0, 0), cov(0, 1), cov(0, 3), cov(1, 0), cov(1, 1), cov(1, 3), cov(3, 0), cov(3, 1), cov(3, 3);
  trajectory_.push_back(estimate_.pose);
  return estimate_;
}

std::vector<core::Pose2> Mapper::trajectory() const { return graph_ ? graph_->trajectory() : trajectory_; }

int Mapper::loopClosures() const { return graph_ ? graph_->loopClosures() : 0; }

OccupancyMap Mapper::map() const {
  if (estimate_.scans == 0) return OccupancyMap();
  if (graph_) return graph_->map();
  return toOccupancyMap(*builder_->getCurrentlyBuiltMetricMap()->mapByClass<mrpt::maps::COccupancyGridMap2D>());
}

}  // namespace localization
}  // namespace amigobot_tracking
