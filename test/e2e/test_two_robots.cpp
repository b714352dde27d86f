// End to end, the paper's experiment (Section 5.3) on two emulators: launch/two_robots.launch
// with the target driven by scripts/nodes/scripted_teleop.py straight through the virtual box of
// config/virtual_obstacles.yaml and back above it, the tracker following. Judged from both
// emulators: their true poses (status sockets) and the tracker's command journal.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include <std_msgs/Int32.h>
#include <std_srvs/Empty.h>

#include "experiment.h"
#include "judge.h"

using e2e::EmulatorStatus;
using e2e::requiredParam;

namespace {

// One sample of both robots' ground truth, taken back to back (within a millisecond or so).
struct PairSample {
  EmulatorStatus target, tracker;
  double error = 0.0;  // [m] |target position - tracker's true offset point|
};

// Polls both emulators' status sockets at 50 Hz on its own thread, so a busy ROS callback
// queue cannot thin the record the clearance is judged on.
class PairRecorder {
 public:
  PairRecorder(int target_port, int tracker_port) : target_(target_port), tracker_(tracker_port) {
    thread_ = std::thread([this] {
      while (!stop_) {
        PairSample s;
        if (target_.tryTruth(&s.target) && tracker_.tryTruth(&s.tracker)) {
          s.error = (Eigen::Vector2d(s.target.pose.x, s.target.pose.y) - e2e::offsetPoint(s.tracker, e2e::kOffset)).norm();
          std::lock_guard<std::mutex> lock(mutex_);
          samples_.push_back(s);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    });
  }
  ~PairRecorder() { stop(); }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  std::vector<PairSample> samples() {
    std::lock_guard<std::mutex> lock(mutex_);
    return samples_;
  }

 private:
  e2e::GroundTruth target_, tracker_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::vector<PairSample> samples_;
  std::thread thread_;
};

// The virtual obstacle two_robots.test loads (config/virtual_obstacles.yaml): the paper's
// square as its circumscribed disk.
const Eigen::Vector2d kBoxCenter(1.5, 0.0);
constexpr double kBoxRadius = 0.25;   // [m]
constexpr double kBodyRadius = 0.18;  // [m] AmigoBot (config/robots/amigo.yaml)

double bodyClearance(const EmulatorStatus& s) {
  return (Eigen::Vector2d(s.pose.x, s.pose.y) - kBoxCenter).norm() - kBoxRadius - kBodyRadius;
}

bool callEmpty(const std::string& service, double timeout) {
  return e2e::waitFor([&] {
    std_srvs::Empty empty;
    return ros::service::waitForService(service, ros::Duration(1.0)) && ros::service::call(service, empty);
  }, timeout);
}

}  // namespace

// The target (teleoperated, not avoiding) crosses the virtual box; the tracker must never
// touch it, command only inside the diamond, and be back on the target (|e| within rho_inf
// plus the pose-lag tolerance) once the target has come round and stopped.
TEST(E2E, TwoRobotsTrackerFollowsAroundTheVirtualObstacle) {
  ros::NodeHandle nh;
  e2e::GroundTruth target_truth(requiredParam<int>("target_status_port"));
  e2e::GroundTruth tracker_truth(requiredParam<int>("tracker_status_port"));
  std::mutex mutex;
  int segment = -2;  // the teleop's ~segment: -1 waiting, i running, segments once done
  ros::Subscriber segment_sub = nh.subscribe<std_msgs::Int32>(
      "/target/scripted_teleop/segment", 10, [&](const std_msgs::Int32::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        segment = m->data;
      });
  const auto teleopSegment = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    return segment;
  };
  const int segments = requiredParam<int>("teleop_segments");

  // The operator's sequence of two_robots.launch: tracker motors, then tracking.
  ASSERT_TRUE(e2e::waitFor([&] {
    EmulatorStatus s;
    return tracker_truth.tryTruth(&s) && s.open;
  }, 90.0)) << "the tracker's driver never opened its emulator";
  ASSERT_TRUE(callEmpty("/tracker/enable_motors", 60.0));
  ASSERT_TRUE(tracker_truth.waitForRobotReady(30.0)) << "the tracker's motors never came on";
  ASSERT_TRUE(e2e::callTrigger("/tracker/tracking/enable", 60.0));
  PairRecorder recorder(requiredParam<int>("target_status_port"), requiredParam<int>("tracker_status_port"));
  // The target stands at its start until the tracker is on it (from 0.5 m away: a few s).
  ASSERT_TRUE(e2e::waitFor([&] {
    const auto s = recorder.samples();
    return !s.empty() && s.back().error < e2e::kRhoInf;
  }, 90.0)) << "the tracker never reached the standing target";
  ASSERT_TRUE(e2e::waitFor([&] { return teleopSegment() == -1; }, 60.0)) << "the teleop is not waiting";
  ASSERT_TRUE(target_truth.waitForRobotReady(30.0)) << "the teleop did not enable the target's motors";
  ASSERT_TRUE(e2e::callTrigger("/target/scripted_teleop/start", 30.0));
  const double started_at = target_truth.truth().t;
  // The script lasts 40.5 s; generous for a loaded machine's late start.
  ASSERT_TRUE(e2e::waitFor([&] { return teleopSegment() == segments; }, 120.0)) << "the teleop never finished";
  // Settling: the target stops at (0.3, 1.0), which the tracker reaches without passing the
  // box (measured: it is back within 0.01 m while the target still drives along y = 1, about
  // 6 s before the end of the script); 12 s more, the last 5 judged.
  const double settle = 12.0, final_window = 5.0;
  ros::WallDuration(settle).sleep();
  recorder.stop();
  const auto samples = recorder.samples();
  ASSERT_GT(samples.size(), 500u) << "too few ground-truth samples";

  // The scenario happened: the target's body centre went through the box.
  double target_in_box = 1e9;
  for (const PairSample& s : samples) {
    target_in_box = std::min(target_in_box, (Eigen::Vector2d(s.target.pose.x, s.target.pose.y) - kBoxCenter).norm());
  }
  EXPECT_LT(target_in_box, kBoxRadius) << "the target never crossed the virtual box";

  // Never touched. Between two samples dt apart (emulator clock) the body moves at most
  // v_max dt (every setpoint is inside the diamond, and the firmware only ramps toward it),
  // and clearance is 1-Lipschitz in position: the lowest clearance between samples with
  // clearances c0, c1 is at least (c0 + c1 - v_max dt) / 2. That bound must stay > 0.
  double sampled = 1e9, between = 1e9, closest_t = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double c = bodyClearance(samples[i].tracker);
    if (c < sampled) {
      sampled = c;
      closest_t = samples[i].tracker.t;
    }
    if (i == 0) continue;
    const double dt = samples[i].tracker.t - samples[i - 1].tracker.t;
    between = std::min(between, 0.5 * (bodyClearance(samples[i - 1].tracker) + c - e2e::kVMax * dt));
  }
  EXPECT_GT(between, 0.0) << "the tracker's body may have touched the box (sampled clearance " << sampled << " m)";
  RecordProperty("body_clearance_mm", static_cast<int>(1e3 * sampled));
  RecordProperty("body_clearance_bound_mm", static_cast<int>(1e3 * between));

  // Every setpoint pair that reached the tracker's emulator is inside the diamond (the
  // protocol's quantisation rounds toward the inside: no slack).
  const auto commands = e2e::readCommandLog(requiredParam<std::string>("command_log"));
  ASSERT_GT(commands.size(), 200u) << "too few commands reached the tracker";
  double worst_norm = 0.0, slowest_v = 0.0;
  for (const auto& c : commands) {
    const double norm = std::abs(c.v) / e2e::kVMax + std::abs(c.w) / e2e::kWMax;
    EXPECT_LE(norm, 1.0 + 1e-9) << c.command << " at t = " << c.t << ": v " << c.v << " w " << c.w;
    worst_norm = std::max(worst_norm, norm);
    slowest_v = std::min(slowest_v, c.v);
  }
  RecordProperty("wire_commands", static_cast<int>(commands.size()));
  RecordProperty("most_negative_v_mm_s", static_cast<int>(1e3 * slowest_v));  // < 0: it backed up

  // Following again: over the last seconds (the target standing) the true error is within
  // rho_inf plus the pose-lag tolerance at every sample.
  const double end_t = samples.back().tracker.t;
  double final_max = 0.0;
  std::string trace;  // every 2 s: t, both true positions, |e| (for a failure's message and the log)
  double next_trace = 0.0;
  for (const PairSample& s : samples) {
    if (s.tracker.t >= end_t - final_window) final_max = std::max(final_max, s.error);
    if (s.target.t - started_at < next_trace) continue;
    next_trace += 2.0;
    char line[128];
    std::snprintf(line, sizeof(line), "t %.1f target (%.2f, %.2f) tracker (%.2f, %.2f) |e| %.3f\n",
                  s.target.t - started_at, s.target.pose.x, s.target.pose.y, s.tracker.pose.x, s.tracker.pose.y,
                  s.error);
    trace += line;
  }
  // localization:=map: the target's pose is the target robot's own localisation and the
  // tracker's its own, so the true final error may carry both localisation errors.
  const double loc_tol = ros::param::param("~localization_tolerance", 0.0);
  EXPECT_LT(final_max, e2e::kRhoInf + e2e::kPoseLagTolerance + loc_tol) << trace;
  std::printf("%s", trace.c_str());
  RecordProperty("final_error_max_mm", static_cast<int>(1e3 * final_max));
  std::printf("target passed %.3f m from the box centre; tracker body clearance %.3f m (at t %.1f, bound between "
              "samples %.3f m); %zu wire commands, max diamond norm %.3f, most negative v %.3f m/s; final max |e| "
              "%.3f m\n",
              target_in_box, sampled, closest_t, between, commands.size(), worst_norm, slowest_v, final_max);
}
