#include "amigobot_tracking/localization/engine.h"

#include <stdexcept>

#include "amigobot_tracking/localization/localization_verdict.h"
#include "amigobot_tracking/localization/localizer.h"
#include "amigobot_tracking/localization/mapper.h"

namespace amigobot_tracking {
namespace localization {
namespace {

// Localisation on a known map: the Localizer, the verdict ("localized" only when the match
// and the pose agree), and initial_pose applied at the first scan (where the robot is then).
class MapEngine : public Engine {
 public:
  MapEngine(const LocalizationConfig& config, const OccupancyMap& map)
      : config_(config),
        localizer_(config, map),
        verdict_(VerdictConfig{config.min_match, config.localized_match, config.max_correction, config.max_correction,
                               config.localized_window}) {}

  const PoseEstimate& update(const RangeScan& scan, const core::Pose2& odom_base) override {
    if (!pose_set_) setPose(config_.initial_pose, odom_base);
    estimate_ = localizer_.update(scan, odom_base);
    estimate_.localized =
        verdict_.update({estimate_.match, estimate_.correction, estimate_.correction_angle}) ==
        LocalizationVerdict::State::kLocalized;
    estimate_.not_localized = verdict_.reason();
    return estimate_;
  }
  const PoseEstimate& estimate() const override { return estimate_; }
  std::string setPose(const core::Pose2& map_base, const core::Pose2& odom_base) override {
    localizer_.setPose(map_base, odom_base);
    poseTaken("initial pose set, no scan agreed with it yet");
    return "";
  }
  std::string globalSearch(const RangeScan& scan, const core::Pose2& odom_base, GlobalSearch* result) override {
    const GlobalSearch r = localizer_.relocalize(scan, odom_base);
    *result = GlobalSearch{r.found, r.pose, r.match, r.candidates};
    if (r.found) poseTaken("relocalised, no scan agreed with the pose yet");
    return "";
  }
  OccupancyMap map() const override { return localizer_.map(); }
  bool mapGrows() const override { return false; }
  std::string mapToSave(OccupancyMap*) const override {
    return "nothing to save: mode is localization (the map is " +
           (config_.use_map_topic ? std::string("the map topic's") : config_.map_file) + ")";
  }
  bool measuresMatch() const override { return true; }

 private:
  // Until a scan is measured at a new pose, it is the operator's (or the search's) word only.
  void poseTaken(const std::string& why) {
    pose_set_ = true;
    verdict_.poseSet();
    estimate_ = localizer_.estimate();
    estimate_.localized = false;
    estimate_.not_localized = why;
  }

  LocalizationConfig config_;
  Localizer localizer_;
  LocalizationVerdict verdict_;
  PoseEstimate estimate_;
  bool pose_set_ = false;
};

// Mapping: the Mapper; its map is made of its own scans, so every scan "matches".
class MappingEngine : public Engine {
 public:
  explicit MappingEngine(const LocalizationConfig& config) : config_(config), mapper_(config) {}

  const PoseEstimate& update(const RangeScan& scan, const core::Pose2& odom_base) override {
    return mapper_.update(scan, odom_base);
  }
  const PoseEstimate& estimate() const override { return mapper_.estimate(); }
  std::string setPose(const core::Pose2&, const core::Pose2&) override {
    return "/initialpose ignored: mode is mapping";
  }
  std::string globalSearch(const RangeScan&, const core::Pose2&, GlobalSearch*) override {
    return "global localization needs mode localization (mode is mapping)";
  }
  OccupancyMap map() const override { return mapper_.map(); }
  bool mapGrows() const override { return true; }
  std::string mapToSave(OccupancyMap* map) const override {
    *map = mapper_.map();
    return "";
  }
  bool measuresMatch() const override { return false; }

 private:
  LocalizationConfig config_;
  Mapper mapper_;
};

}  // namespace

std::unique_ptr<Engine> makeEngine(const LocalizationConfig& config) {
  if (config.mode == "mapping") return std::make_unique<MappingEngine>(config);
  if (config.mode != "localization") throw std::runtime_error("parameter ~mode: unknown mode '" + config.mode + "'");
  try {
    return std::make_unique<MapEngine>(config, loadMap(config.map_file));
  } catch (const std::exception& e) {
    throw std::runtime_error("parameter ~map_file: " + std::string(e.what()));
  }
}

std::unique_ptr<Engine> makeEngine(const LocalizationConfig& config, const OccupancyMap& map) {
  if (map.empty()) throw std::runtime_error("the map is empty (0 cells)");
  return std::make_unique<MapEngine>(config, map);
}

}  // namespace localization
}  // namespace amigobot_tracking
