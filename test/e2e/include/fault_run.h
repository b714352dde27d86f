// What the fault tests of test_e2e share (test_fault_injection.cpp, test_cpu_starvation.cpp,
// test_wrong_initial_pose.cpp, test_kidnap.cpp): the start of a tracking run judged from the
// emulator, and a sampler of the believed pose (tf map -> base_link) against the truth for the
// tests that localise on the map.
#pragma once

#include <gtest/gtest.h>

#include <std_srvs/Empty.h>
#include <tf2_ros/transform_listener.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "judge.h"

namespace e2e {

// The driver has the emulated robot open with its motors on, the robot drives (true speed
// above 0.1 m/s within drive_timeout [s]; the map localisation needs longer to start), and
// `settle` [s] more have passed, so a fault strikes a robot in full tracking.
inline ::testing::AssertionResult trackingStarted(GroundTruth& truth, double drive_timeout = 60.0,
                                                  double settle = 3.0) {
  const ::testing::AssertionResult ready = truth.waitForRobotReady(60.0);
  if (!ready) return ready;
  if (!waitFor([&] { return truth.truth().v > 0.1; }, drive_timeout)) {
    return ::testing::AssertionFailure() << "the robot never drove (true v <= 0.1 m/s for " << drive_timeout << " s)";
  }
  ros::Duration(settle).sleep();
  return ::testing::AssertionSuccess();
}

struct PoseSample {
  EmulatorStatus truth;
  double loc_error = std::numeric_limits<double>::quiet_NaN();  // [m] |believed - true|, NaN: no tf
};

// Samples the truth and the believed pose at 20 Hz on its own thread.
class PoseSampler {
 public:
  explicit PoseSampler(int status_port) : truth_(status_port), listener_(tf_) {
    thread_ = std::thread([this] { run(); });
  }
  ~PoseSampler() {
    stop_ = true;
    thread_.join();
  }
  PoseSampler(const PoseSampler&) = delete;
  PoseSampler& operator=(const PoseSampler&) = delete;
  std::vector<PoseSample> samples() {
    std::lock_guard<std::mutex> lock(mutex_);
    return samples_;
  }
  PoseSample last() {
    std::lock_guard<std::mutex> lock(mutex_);
    return samples_.empty() ? PoseSample{} : samples_.back();
  }

 private:
  void run() {
    while (!stop_ && ros::ok()) {
      PoseSample s;
      if (truth_.tryTruth(&s.truth)) {
        try {
          const auto b = tf_.lookupTransform("map", "base_link", ros::Time(0));
          s.loc_error = std::hypot(b.transform.translation.x - s.truth.pose.x, b.transform.translation.y - s.truth.pose.y);
        } catch (const tf2::TransformException&) {
        }
        std::lock_guard<std::mutex> lock(mutex_);
        samples_.push_back(s);
      }
      ros::WallDuration(0.05).sleep();
    }
  }
  GroundTruth truth_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::vector<PoseSample> samples_;
  std::thread thread_;
};

// Samples that moved (true v or w not zero) while the believed pose was more than `lost` [m]
// off, from emulator time `since` on; *lost_samples counts the samples that far off.
inline int movedWhileLost(const std::vector<PoseSample>& samples, double since, double lost, int* lost_samples) {
  int moved = 0;
  *lost_samples = 0;
  for (const PoseSample& s : samples) {
    if (s.truth.t < since || !(s.loc_error > lost)) continue;
    ++*lost_samples;
    if (s.truth.v != 0.0 || s.truth.w != 0.0) ++moved;
  }
  return moved;
}

// What a localisation fault and its recovery through global localisation did (emulator times).
struct Relocalised {
  EmulatorStatus stopped;   // the first standstill after the fault
  double lost_until = 0.0;  // the end of the wait while lost
  EmulatorStatus asked;     // when global_localization was called
  EmulatorStatus resumed;   // the first true speed above 0.1 m/s after it
  PoseSample end;           // `settle` s later
  double settle_path = 0.0; // [m] the true path driven over those `settle` s
  double zero_at = -1.0;    // the first zero setpoint on the wire since the fault
  int lost = 0;             // samples from the standstill on with the believed pose > lost_error off
  int moved_lost = 0;       // of those, samples that moved
};

// After a localisation fault at emulator time `fault_t` (a wrong /initialpose, a kidnap): the
// robot must come to a standstill within 10 s; it is left lost for 3 s (whatever ICP makes of
// it), then global_localization is called and it must drive again within 60 s; `settle` s
// later the run ends. The caller judges *out against its own bounds.
inline ::testing::AssertionResult relocalised(GroundTruth& truth, PoseSampler& sampler, const std::string& command_log,
                                              double fault_t, double lost_error, Relocalised* out,
                                              double settle = 4.0) {
  if (!truth.waitForStandstill(10.0, &out->stopped)) {
    return ::testing::AssertionFailure() << "the robot kept driving on a wrong pose";
  }
  ros::Duration(3.0).sleep();
  out->lost_until = truth.truth().t;
  std_srvs::Empty call;
  out->asked = truth.truth();
  if (!ros::service::call("global_localization", call)) {
    return ::testing::AssertionFailure() << "global_localization failed";
  }
  if (!waitFor([&] { return truth.tryTruth(&out->resumed) && out->resumed.v > 0.1; }, 60.0)) {
    return ::testing::AssertionFailure() << "tracking never resumed after global_localization";
  }
  ros::Duration(settle).sleep();
  out->end = sampler.last();
  const std::vector<PoseSample> samples = sampler.samples();
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i - 1].truth.t >= out->end.truth.t - settle)
      out->settle_path += std::hypot(samples[i].truth.pose.x - samples[i - 1].truth.pose.x,
                                     samples[i].truth.pose.y - samples[i - 1].truth.pose.y);
  out->zero_at = firstZeroSetpoint(readCommandLog(command_log), fault_t);
  out->moved_lost = movedWhileLost(samples, out->stopped.t, lost_error, &out->lost);
  return ::testing::AssertionSuccess();
}

}  // namespace e2e
