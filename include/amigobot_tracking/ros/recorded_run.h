// Figures of merit of a run recorded on the ROS stack (rosbag of sim.launch), computed
// with the offline simulator's definitions (core/metrics.h) so the two compare: the
// controller's view from TrackingState, safety from the emulator's ground truth, and the
// diamond check of every cmd_vel the driver received.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "amigobot_tracking/TrackingState.h"
#include "amigobot_tracking/sim/metrics.h"
#include "amigobot_tracking/core/robot/robot_description.h"
#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/sim/json.h"
#include "amigobot_tracking/sim/simulator.h"
#include "amigobot_tracking/sim/tracking_verdict.h"
#include "amigobot_tracking/world/world.h"

namespace amigobot_tracking {
namespace ros_layer {

struct RecordedRunConfig {
  world::World world;             // physical obstacles (the emulator's world file)
  double robot_radius = core::RobotDescription().robot_radius;  // [m] R
  double offset = 0.3;            // [m] r, offset of the controlled point p_r
  double rho_inf = 0.1;           // [m] for the plots' metadata
  double v_max = core::RobotDescription().v_max;  // [m/s] the robot's diamond (its robot file)
  double w_max = core::RobotDescription().w_max;  // [rad/s]
  double settle_time = 0.5;       // [s] estimator transient left out of its "settled" figure
  bool body_safe = true;          // the run's body_safe: effective radius R + r around p_r
  double velocity_window = 1.0;   // [s] the target's true velocity: central difference over this span
  std::string law = "paper";      // core::controlLawNames() or escape (paper + tangential_avoidance)
  sim::TrackingVerdictConfig verdict;  // rho_inf, tolerance, recovery time, band (delta)

  std::string validate() const;   // empty when valid, else names the bad field
};

// What the run shows beyond sim::RunMetrics.
struct RecordedRunSummary {
  sim::RunMetrics metrics;           // enabled control steps; clearances from ground truth
  std::uint64_t states = 0;           // TrackingState messages seen (any)
  std::uint64_t truth_samples = 0;    // ground-truth poses seen
  std::uint64_t commands = 0;         // cmd_vel messages
  std::uint64_t command_violations = 0;  // cmd_vel outside the diamond
  double max_command_norm = 0.0;      // max |v|/v_max + |w|/w_max over cmd_vel
  double min_clearance_world = std::numeric_limits<double>::infinity();    // [m] true body to the world (disks, walls, polygons)
  double min_clearance_virtual = std::numeric_limits<double>::infinity();  // [m] true body to virtual disks
  double min_clearance_people = std::numeric_limits<double>::infinity();   // [m] true body to the world's people (in min_clearance_world too)
  std::uint64_t virtual_obstacles = 0;  // most virtual obstacles present at once
  double within_rho_fraction = 0.0;   // share of enabled steps with |e| < rho
  double path_length = 0.0;           // [m] true distance travelled while enabled
  sim::TrackingVerdict tracking;      // judged on the true error (sim/tracking_verdict.h)

  bool collided() const { return metrics.body_collisions > 0; }
  bool ran() const { return metrics.steps >= 20 && truth_samples > 0 && path_length > 0.2; }
};

class RecordedRun {
 public:
  explicit RecordedRun(RecordedRunConfig config);

  // [s] stamp, true pose of base_link in map, and the emulator's clock at that pose (where
  // the world's people are: world::worldAt; ground_truth_localization's ground_truth_clock).
  void addTruth(double t, const core::Pose2& pose, double world_t = 0.0);
  void addVirtualObstacles(std::vector<core::Disk> disks);
  // Every disk seen: the world's and each virtual obstacle ever present (for the plots).
  std::vector<core::Disk> allObstacles() const;
  void addCommand(double v, double w);                  // every cmd_vel
  void addState(const TrackingState& state);            // one control step
  // Scores the steps (the target's velocity needs the steps after each one). Rows and
  // summary are complete afterwards; later states are ignored.
  void finish();

  const std::vector<sim::CsvRow>& rows() const { return rows_; }
  RecordedRunSummary summary() const;

 private:
  struct Step {
    double t = 0.0;
    sim::MetricSample sample;
    sim::CsvRow row{};
    Eigen::Vector2d p_d = Eigen::Vector2d::Zero();
    Eigen::Vector2d v_hat = Eigen::Vector2d::Zero();
  };
  // The target's velocity at step k: central difference of p_d over velocity_window.
  Eigen::Vector2d targetVelocity(std::size_t k) const;

  RecordedRunConfig config_;
  world::World room_;  // config_.world with its people where they are at the latest truth
  sim::MetricsAccumulator accumulator_;
  RecordedRunSummary summary_;
  std::vector<core::Disk> virtual_, virtual_seen_;
  std::vector<sim::CsvRow> rows_;
  std::vector<Step> steps_;
  std::vector<sim::TrackingSample> tracking_;
  bool have_truth_ = false, finished_ = false;
  core::Pose2 truth_, last_path_pose_;
  bool have_path_pose_ = false;
  double t0_ = -1.0;
  std::uint64_t within_rho_ = 0;
};

// The figures of metrics.json: the shared metrics (sim/json.h) and the recorded-run ones.
void to_json(sim::Json& json, const RecordedRunSummary& summary);

// metrics.json of a recorded run (same keys as the offline simulator's where they mean
// the same, plus the recorded-run ones, `law` and the `tracking` verdict); `scenario` gives
// plot_run.py its metadata.
std::string recordedRunJson(const RecordedRunSummary& summary, const RecordedRunConfig& config,
                            const std::vector<core::Disk>& all_obstacles, const std::string& name);

}  // namespace ros_layer
}  // namespace amigobot_tracking
