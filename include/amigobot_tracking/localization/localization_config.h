// The localisation nodelet's one parameter set (ROS-free): what it does (mapping or
// localisation on a map file), its frames and publishing rates, and the ICP, update and
// global-relocalisation settings of the Localizer and the Mapper. SI units, described once by
// localizationFields() (config/localization.yaml, the table in docs/ros_api.md, the ROS reader).
#pragma once

#include <string>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace localization {

struct IcpConfig {
  int max_iterations = 60;             // per alignment
  double max_correspondence = 0.6;     // [m] first pairing distance, shrunk to min_correspondence
  double min_correspondence = 0.05;    // [m] final pairing distance
  int max_points = 240;                // scan points used (evenly decimated)
};

struct GlobalConfig {
  double xy_step = 0.2;        // [m] candidate positions over the free space
  double yaw_step = 0.0873;    // [rad] candidate headings (5 deg)
  double clearance = 0.15;     // [m] candidates at least this far from an occupied cell
  int candidates = 12;         // best coarse candidates refined by ICP
  double min_match = 0.6;      // [-] fraction of beams on the map accepting a relocalisation
};

struct GraphConfig {
  double keyframe_travel = 0.3;  // [m] travel between keyframes of the pose graph
  double loop_radius = 4.0;      // [m] old keyframes this close are loop candidates
  double loop_min_match = 0.7;   // [-] fraction of a keyframe's points on the old ones accepting a loop
  int loop_min_gap = 20;         // keyframes between a keyframe and its loop candidates
};

struct LocalizationConfig {
  std::string mode = "localization";  // mapping | localization
  std::string mapping_method = "graph";  // mapping: graph (pose graph, closes loops) | icp (MRPT's ICP-SLAM)
  std::string map_file;               // localization: the map to load; mapping: ~save_map's default
  bool use_map_topic = false;         // localization: the map from the `map` topic (a map_server), not map_file
  core::Pose2 initial_pose;           // [m, m, rad] map -> base at start (and the map origin's offset when mapping)
  std::string global_frame = "map", odom_frame = "odom", base_frame = "base_footprint";
  double transform_tolerance = 0.1;  // [s] map -> odom stamped this far ahead
  double tf_rate = 30.0;             // [Hz] map -> odom republished between scans (>= 20)
  double map_publish_period = 2.0;   // [s] mapping: the growing map republished this often
  double resolution = 0.05;          // [m] mapping: cell size of the built grid
  double min_travel = 0.05;          // [m] travel between scan matches (below: odometry only)
  double min_rotation = 0.05;        // [rad] rotation between scan matches
  double match_distance = 0.1;       // [m] a beam within this of an occupied cell matches the map
  double min_match = 0.4;            // [-] fraction of matching beams below which the pose is "lost"
  double localized_match = 0.8;      // [-] "localized" needs localized_window scans in a row matching this much
  int localized_window = 5;          // scans in a row that must agree with the pose to say "localized"
  double max_correction = 0.1;       // [m] a larger scan-matched correction is a jump (the tracking bound rho_inf)
  double range_max = 10.0;           // [m] farther echoes are ignored
  IcpConfig icp;
  GlobalConfig global;
  GraphConfig graph;

  // "" when valid, else "key: reason" for the first rule across fields that is broken.
  std::string validate() const;
};

// The one description of LocalizationConfig.
const core::FieldTable<LocalizationConfig>& localizationFields();

}  // namespace localization
}  // namespace amigobot_tracking
