#include "amigobot_tracking/localization/log_replay.h"

#include <algorithm>
#include <ctime>
#include <optional>
#include <random>

#include "amigobot_tracking/localization/localizer.h"
#include "amigobot_tracking/localization/map_drawing.h"
#include "amigobot_tracking/localization/mapper.h"
#include "amigobot_tracking/localization/poses.h"

namespace amigobot_tracking {
namespace localization {

namespace {

double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// The node's worker: it takes the newest scan when free and drops older ones that waited.
// Each update takes its CPU time here; a scan's online pose is the engine's estimate for it,
// or, for a dropped scan, the last map -> odom composed with the scan's odometry.
class NodeWorker {
 public:
  NodeWorker(const CarmenLog& log, Mapper* mapper, ReplayResult* result) : log_(log), mapper_(mapper), result_(result) {
    result->online.resize(log.scans.size());
  }
  void arrive(std::size_t i) {
    const double t = log_.scans[i].scan.stamp;
    if (pending_ && free_at_ <= t) run(*pending_, free_at_);
    pending_.reset();
    if (free_at_ <= t) {
      run(i, t);
    } else {
      pending_ = i;  // replaced (dropped) if another scan arrives before the worker is free
      result_->online[i] = compose(map_to_odom_, log_.scans[i].odometry);
    }
  }
  void finish() {
    if (pending_) run(*pending_, free_at_);
  }

 private:
  void run(std::size_t i, double start) {
    const double before = cpuSeconds();
    const PoseEstimate& e = mapper_->update(log_.scans[i].scan, log_.scans[i].odometry);
    const double cost = cpuSeconds() - before;
    result_->max_update = std::max(result_->max_update, cost);
    free_at_ = start + cost;
    map_to_odom_ = e.map_to_odom;
    result_->online[i] = e.pose;
    processed_.push_back(i);
  }

  const CarmenLog& log_;
  Mapper* mapper_;
  ReplayResult* result_;
  std::optional<std::size_t> pending_;
  double free_at_ = -1e300;
  core::Pose2 map_to_odom_;
  std::vector<std::size_t> processed_;

 public:
  // The scans given to the mapper, in order.
  const std::vector<std::size_t>& processed() const { return processed_; }
};

void score(const CarmenLog& log, const Relations& relations, ReplayResult* result) {
  std::vector<core::Pose2> odometry;
  for (const LogScan& s : log.scans) {
    result->reference.push_back(s.reference);
    odometry.push_back(s.odometry);
  }
  const Relations& chosen = relations.empty() ? consecutiveRelations(result->reference) : relations;
  result->ate = absoluteError(result->estimate, result->reference);
  result->odometry_ate = absoluteError(odometry, result->reference);
  result->relative = relativeError(result->estimate, chosen);
  if (!result->online.empty()) {
    result->online_ate = absoluteError(result->online, result->reference);
    result->online_relative = relativeError(result->online, chosen);
  }
}

}  // namespace

void driftOdometry(CarmenLog* log, const OdometryDrift& drift) {
  std::mt19937 random(drift.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  core::Pose2 odometry;
  for (std::size_t i = 0; i < log->scans.size(); ++i) {
    if (i > 0) {
      const core::Pose2 step = compose(inverse(log->scans[i - 1].reference), log->scans[i].reference);
      const double distance = std::hypot(step.x, step.y);
      const double scale = drift.scale * (1.0 + drift.noise * normal(random));
      const double heading = (drift.heading_per_metre + drift.noise * normal(random)) * distance;
      odometry = compose(odometry, core::Pose2{scale * step.x, scale * step.y, step.theta + heading});
    }
    log->scans[i].odometry = odometry;
  }
}

ReplayResult replayMapping(const CarmenLog& log, LocalizationConfig config, const Relations& relations) {
  config.mode = "mapping";
  config.initial_pose = log.scans.front().reference;
  ReplayResult result;
  const double start = cpuSeconds();
  Mapper mapper(config);
  NodeWorker worker(log, &mapper, &result);
  for (std::size_t i = 0; i < log.scans.size(); ++i) worker.arrive(i);
  worker.finish();
  result.dropped = static_cast<int>(log.scans.size() - worker.processed().size());
  // The mapper's trajectory has a pose per scan it was given: dropped scans keep their online pose.
  const std::vector<core::Pose2> smoothed = mapper.trajectory();
  result.estimate = result.online;
  for (std::size_t k = 0; k < smoothed.size() && k < worker.processed().size(); ++k) result.estimate[worker.processed()[k]] = smoothed[k];
  result.loop_closures = mapper.loopClosures();
  result.map = mapper.map();
  result.seconds = cpuSeconds() - start;
  score(log, relations, &result);
  return result;
}

ReplayResult replayLocalization(const CarmenLog& log, LocalizationConfig config, const OccupancyMap& map,
                                const Relations& relations) {
  config.mode = "localization";
  ReplayResult result;
  const double start = cpuSeconds();
  Localizer localizer(config, map);
  localizer.setPose(log.scans.front().reference, log.scans.front().odometry);
  for (const LogScan& s : log.scans) result.estimate.push_back(localizer.update(s.scan, s.odometry).pose);
  result.seconds = cpuSeconds() - start;
  score(log, relations, &result);
  return result;
}

OccupancyMap referenceMap(const CarmenLog& log, double resolution, double range_cap) {
  std::vector<const RangeScan*> scans;
  std::vector<core::Pose2> poses;
  for (const LogScan& s : log.scans) {
    scans.push_back(&s.scan);
    poses.push_back(s.reference);
  }
  return drawMap(scans, poses, resolution, range_cap);
}

}  // namespace localization
}  // namespace amigobot_tracking
