#include "amigobot_tracking/localization/log_replay.h"

#include <ctime>

#include "amigobot_tracking/localization/localizer.h"
#include "amigobot_tracking/localization/map_drawing.h"
#include "amigobot_tracking/localization/mapper.h"
#include "amigobot_tracking/localization/poses.h"

namespace amigobot_tracking {
namespace localization {

namespace {

double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

void score(const CarmenLog& log, const Relations& relations, ReplayResult* result) {
  std::vector<core::Pose2> odometry;
  for (const LogScan& s : log.scans) {
    result->reference.push_back(s.reference);
    odometry.push_back(s.odometry);
  }
  result->ate = absoluteError(result->estimate, result->reference);
  result->odometry_ate = absoluteError(odometry, result->reference);
  result->relative = relativeError(result->estimate, relations.empty() ? consecutiveRelations(result->reference) : relations);
}

}  // namespace

void driftOdometry(CarmenLog* log, const OdometryDrift& drift) {
  core::Pose2 odometry;
  for (std::size_t i = 0; i < log->scans.size(); ++i) {
    if (i > 0) {
      const core::Pose2 step = compose(inverse(log->scans[i - 1].reference), log->scans[i].reference);
      const double distance = std::hypot(step.x, step.y);
      odometry = compose(odometry, core::Pose2{drift.scale * step.x, drift.scale * step.y, step.theta + drift.heading_per_metre * distance});
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
  for (const LogScan& s : log.scans) mapper.update(s.scan, s.odometry);
  result.estimate = mapper.trajectory();
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
