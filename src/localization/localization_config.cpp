#include "amigobot_tracking/localization/localization_config.h"

#include <cmath>

namespace amigobot_tracking {
namespace localization {

const core::FieldTable<LocalizationConfig>& localizationFields() {
  using C = LocalizationConfig;
  using core::field;
  static const core::FieldTable<C> table = [] {
    core::FieldTable<C> t;
    t.push_back(field("mode", &C::mode, "-",
                      "localization (on map_file, or the map topic with use_map_topic) or mapping (SLAM by "
                      "mapping_method)",
                      core::oneOf({"mapping", "localization"})));
    t.push_back(field("mapping_method", &C::mapping_method, "-",
                      "mapping: graph (pose graph of keyframes that closes loops; docs/localization.md) or icp (MRPT's "
                      "ICP-SLAM)",
                      core::oneOf({"icp", "graph"})));
    t.push_back(field("map_file", &C::map_file, "-",
                      "map_server YAML: loaded in localization (required unless use_map_topic), or where ~save_map "
                      "(and ~save_map_to without a path) writes in mapping, its folder checked at start"));
    t.push_back(field("use_map_topic", &C::use_map_topic, "-",
                      "localization: the map from the map topic (a map_server's, latched) instead of map_file, as "
                      "amcl's; mode mapping refuses it"));
    core::include(&t, "initial_pose/", &C::initial_pose,
                  core::FieldTable<core::Pose2>{
                      field("x", &core::Pose2::x, "m",
                            "map -> base_frame x at the first scan (mapping: the map's offset)",
                            core::anyValue()),
                      field("y", &core::Pose2::y, "m",
                            "map -> base_frame y at the first scan (mapping: the map's offset)",
                            core::anyValue()),
                      field("yaw", &core::Pose2::theta, "rad",
                            "map -> base_frame heading at the first scan (mapping: the map's offset)",
                            core::anyValue()),
                  });
    t.push_back(field("global_frame", &C::global_frame, "-", "the map frame, parent of odom_frame"));
    t.push_back(field("odom_frame", &C::odom_frame, "-",
                      "odometry frame (tf odom_frame -> base_frame from the driver); not global_frame"));
    t.push_back(field("base_frame", &C::base_frame, "-", "the robot's base frame; not odom_frame"));
    t.push_back(field("transform_tolerance", &C::transform_tolerance, "s",
                      "map -> odom stamped this far ahead, in [0, 2] (as amcl's)",
                      core::interval(0.0, false, 2.0, false)));
    t.push_back(field("tf_rate", &C::tf_rate, "Hz", "map -> odom republished at this rate between scans, >= 20",
                      core::interval(20.0, false, 1000.0, false)));
    t.push_back(field("map_publish_period", &C::map_publish_period, "s",
                      "mapping: the growing map republished this often",
                      core::interval(0.1, false, 3600.0, false)));
    t.push_back(field("resolution", &C::resolution, "m", "mapping: cell size of the built grid, in [0.01, 1]",
                      core::interval(0.01, false, 1.0, false)));
    t.push_back(field("min_travel", &C::min_travel, "m",
                      "travel between scan matches (below it and min_rotation: odometry only)", core::nonNegative()));
    t.push_back(field("min_rotation", &C::min_rotation, "rad",
                      "rotation between scan matches (below it and min_travel: odometry only)",
                      core::interval(0.0, false, M_PI, false)));
    t.push_back(field("match_distance", &C::match_distance, "m",
                      "a beam this close to an occupied cell matches the map",
                      core::interval(0.0, true, 1.0, false)));
    t.push_back(field("min_match", &C::min_match, "-",
                      "fraction of matching beams below which the pose is lost (diagnostics WARN, not localized)",
                      core::interval(0.0, false, 1.0, false)));
    t.push_back(field("localized_match", &C::localized_match, "-",
                      "localized only after localized_window scans in a row match at least this fraction, "
                      ">= min_match",
                      core::interval(0.0, false, 1.0, false)));
    t.push_back(field("localized_window", &C::localized_window, "-",
                      "scans in a row that must agree with the pose (match >= localized_match, correction <= "
                      "max_correction) to say localized",
                      core::interval(1, false, 1000, false)));
    t.push_back(field("max_correction", &C::max_correction, "m",
                      "a scan-matched correction larger than this (as the tracking bound rho_inf) is a jump: not "
                      "localized until localized_window scans agree again; the same number bounds the heading "
                      "correction in rad",
                      core::positive()));
    t.push_back(field("range_max", &C::range_max, "m", "farther echoes are ignored", core::positive()));
    core::include(&t, "icp/", &C::icp,
                  core::FieldTable<IcpConfig>{
                      field("max_iterations", &IcpConfig::max_iterations, "-", "ICP iterations per alignment",
                            core::interval(1, false, 1000, false)),
                      field("max_correspondence", &IcpConfig::max_correspondence, "m",
                            "first ICP pairing distance (the largest error one scan corrects), shrunk to "
                            "min_correspondence",
                            core::positive()),
                      field("min_correspondence", &IcpConfig::min_correspondence, "m",
                            "final ICP pairing distance, <= max_correspondence", core::positive()),
                      field("max_points", &IcpConfig::max_points, "-", "scan points used per match (evenly decimated)",
                            core::interval(10, false, 100000, false)),
                  });
    core::include(&t, "global/", &C::global,
                  core::FieldTable<GlobalConfig>{
                      field("xy_step", &GlobalConfig::xy_step, "m",
                            "relocalisation (~global_localization): candidate position spacing over the free space",
                            core::interval(0.01, false, 5.0, false)),
                      field("yaw_step", &GlobalConfig::yaw_step, "rad",
                            "relocalisation (~global_localization): candidate heading spacing",
                            core::interval(0.005, false, 1.0, false)),
                      field("clearance", &GlobalConfig::clearance, "m",
                            "relocalisation (~global_localization): candidates at least this far from walls (occupied "
                            "cells)",
                            core::nonNegative()),
                      field("candidates", &GlobalConfig::candidates, "-",
                            "relocalisation (~global_localization): best coarse candidates refined by ICP",
                            core::interval(1, false, 1000, false)),
                      field("min_match", &GlobalConfig::min_match, "-",
                            "relocalisation (~global_localization): matching fraction to accept a pose",
                            core::interval(0.0, false, 1.0, false)),
                  });
    core::include(&t, "graph/", &C::graph,
                  core::FieldTable<GraphConfig>{
                      field("keyframe_travel", &GraphConfig::keyframe_travel, "m",
                            "graph mapping: travel between keyframes",
                            core::interval(0.01, false, 10.0, false)),
                      field("loop_radius", &GraphConfig::loop_radius, "m",
                            "graph mapping: old keyframes this close are loop candidates",
                            core::interval(0.1, false, 50.0, false)),
                      field("loop_min_match", &GraphConfig::loop_min_match, "-",
                            "graph mapping: fraction of a keyframe's points on the old ones accepting a loop",
                            core::interval(0.0, false, 1.0, false)),
                      field("loop_min_gap", &GraphConfig::loop_min_gap, "-",
                            "graph mapping: keyframes between a keyframe and its loop candidates",
                            core::interval(2, false, 100000, false)),
                  });
    return t;
  }();
  return table;
}

std::string LocalizationConfig::validate() const {
  const std::string bounds = core::checkFields(localizationFields(), *this);
  if (!bounds.empty()) return bounds;
  if (use_map_topic && mode != "localization") return "use_map_topic: only in mode localization (mode is " + mode + ")";
  if (mode == "localization" && map_file.empty() && !use_map_topic)
    return "map_file: required in localization mode (or use_map_topic: true)";
  if (!initial_pose.isFinite()) return "initial_pose: must be finite";
  if (global_frame.empty()) return "global_frame: must not be empty";
  if (odom_frame.empty()) return "odom_frame: must not be empty";
  if (base_frame.empty()) return "base_frame: must not be empty";
  if (global_frame == odom_frame) return "odom_frame: must differ from global_frame '" + global_frame + "'";
  if (odom_frame == base_frame) return "base_frame: must differ from odom_frame '" + odom_frame + "'";
  if (icp.min_correspondence > icp.max_correspondence)
    return "icp/min_correspondence: must be <= icp/max_correspondence (" + std::to_string(icp.max_correspondence) + ")";
  if (localized_match < min_match) return "localized_match: must be >= min_match (" + std::to_string(min_match) + ")";
  if (1.0 / tf_rate > map_publish_period) return "map_publish_period: must be at least one tf period";
  return "";
}

}  // namespace localization
}  // namespace amigobot_tracking
