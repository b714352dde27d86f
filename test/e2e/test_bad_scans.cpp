// End to end, issue 24 item 4: bad LaserScans at the tracking nodelet's scan topic while it
// tracks (bad_scans.test: laser:=none, this test is the only scan source). A scan the node
// must refuse (angle_increment 0, range_min > range_max, NaN angle_min, only NaN or only
// negative ranges, 100,000 ranges under a 360-beam header) is logged as an ERROR naming the
// field and does not refresh the scan's age: zero on the wire within scan_timeout + 0.1 s,
// still while it lasts, driving again once good scans return. A scan with NaN, -inf and
// negative beams among readings, and one of 100,000 beams over one turn, are scans (REP 117):
// the robot keeps driving. Judged from the emulator's ground truth and its command journal.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/LaserScan.h>

#include "circle_target.h"
#include "judge.h"
#include "one_turn_scan.h"
#include "periodic_thread.h"
#include "rosout_log.h"
#include "stack_timing.h"

using e2e::CircleTarget;
using e2e::EmulatorStatus;
using e2e::requiredParam;

namespace {

// The stack's timeouts and periods: stack_timing.h.
using namespace stack_timing;
constexpr double kBadFor = 1.5;  // [s] each bad scan is sent this long: three scan timeouts
constexpr float kInfRange = std::numeric_limits<float>::infinity(), kNaNRange = std::numeric_limits<float>::quiet_NaN();

// The good scan of an empty room: nothing within range_max.
sensor_msgs::LaserScan goodScan() { return amigobot_test::oneTurnScan(kInfRange); }

sensor_msgs::LaserScan spoiled(const std::function<void(sensor_msgs::LaserScan&)>& spoil) {
  sensor_msgs::LaserScan s = goodScan();
  spoil(s);
  return s;
}

// Publishes the current scan at 10 Hz, stamped now. switchTo() swaps it right after a
// publication, so the last scan of the old kind left just before it returns.
class ScanSource {
 public:
  explicit ScanSource(ros::NodeHandle& nh) : pub_(nh.advertise<sensor_msgs::LaserScan>("/scan", 2)) {}

  void switchTo(const sensor_msgs::LaserScan& scan) {
    std::unique_lock<std::mutex> lock(mutex_);
    next_ = scan;
    pending_ = true;
    swapped_.wait(lock, [this] { return !pending_; });
  }

 private:
  void publish() {
    std::unique_lock<std::mutex> lock(mutex_);
    scan_.header.stamp = ros::Time::now();
    pub_.publish(scan_);
    if (pending_) {
      scan_ = next_;
      pending_ = false;
      swapped_.notify_all();
    }
  }

  ros::Publisher pub_;
  std::mutex mutex_;
  std::condition_variable swapped_;
  sensor_msgs::LaserScan scan_ = goodScan(), next_;
  bool pending_ = false;
  e2e::PeriodicThread thread_{10.0, [this] { publish(); }};  // last: stops first
};

struct BadScan {
  std::string what;
  sensor_msgs::LaserScan scan;
  std::string field;  // the ERROR must contain it; "" for a scan that must be used
};

}  // namespace

TEST(E2E, BadScansAreRefusedByNameAndStopTheRobot) {
  ros::NodeHandle nh;
  e2e::RosoutLog errors(nh, rosgraph_msgs::Log::ERROR);
  e2e::GroundTruth truth(requiredParam<int>("status_port"));
  const std::string command_log = requiredParam<std::string>("command_log");
  CircleTarget target;
  ScanSource source(nh);
  ASSERT_TRUE(truth.waitForRobotReady(60.0));
  ASSERT_TRUE(e2e::waitFor([&] { return truth.truth().v > 0.1; }, 60.0)) << "the robot never drove";
  ros::Duration(2.0).sleep();
  const int manager = e2e::nodePid("/amigobot_manager");
  ASSERT_GT(manager, 0);

  const std::vector<BadScan> refused = {
      {"angle_increment 0", spoiled([](sensor_msgs::LaserScan& s) { s.angle_increment = 0.0f; }), "angle_increment:"},
      {"range_min > range_max", spoiled([](sensor_msgs::LaserScan& s) { s.range_min = 10.0f; }), "range_max:"},
      {"NaN angle_min", spoiled([](sensor_msgs::LaserScan& s) { s.angle_min = kNaNRange; }), "angle_min:"},
      {"only NaN ranges", spoiled([](sensor_msgs::LaserScan& s) { s.ranges.assign(360, kNaNRange); }), "(360 NaN"},
      {"only negative ranges", spoiled([](sensor_msgs::LaserScan& s) { s.ranges.assign(360, -1.0f); }),
       "0 NaN, 360 below range_min"},
      {"100,000 ranges under a 360-beam header",
       spoiled([](sensor_msgs::LaserScan& s) { s.ranges.assign(100000, 2.0f); }), "ranges: 100000 beams"},
  };
  double worst_zero = 0.0, worst_standstill = 0.0, worst_resume = 0.0;
  for (const BadScan& bad : refused) {
    const std::size_t since = errors.count();
    source.switchTo(bad.scan);
    const EmulatorStatus before = truth.truth();
    EmulatorStatus stopped;
    const bool stood = truth.waitForStandstill(kBadFor, &stopped);
    ros::WallDuration(std::max(0.0, kBadFor - (truth.truth().t - before.t))).sleep();
    const EmulatorStatus still = truth.truth();
    source.switchTo(goodScan());
    const EmulatorStatus good_again = truth.truth();
    EXPECT_TRUE(stood) << bad.what << ": the robot kept driving";
    EXPECT_EQ(still.v, 0.0) << bad.what << ": the robot moved while the scans were refused";
    std::string line;
    EXPECT_TRUE(errors.waitForMentionOfAll({"scan refused", bad.field}, 2.0, since, &line))
        << bad.what << ": no ERROR naming '" << bad.field << "'";
    ASSERT_TRUE(e2e::waitFor([&] { return truth.truth().v > 0.1; }, 20.0)) << bad.what << ": tracking never resumed";
    const EmulatorStatus resumed = truth.truth();

    const double zero_at = e2e::firstZeroSetpoint(e2e::readCommandLog(command_log), before.t);
    ASSERT_GE(zero_at, 0.0) << bad.what << ": no zero setpoint reached the emulator";
    EXPECT_LE(zero_at - before.t, kScanTimeout + kControlPeriod + kDriverSlot + 0.1) << bad.what << ": zero late";
    worst_zero = std::max(worst_zero, zero_at - before.t);
    worst_standstill = std::max(worst_standstill, stopped.t - before.t);
    worst_resume = std::max(worst_resume, resumed.t - good_again.t);
    std::printf("%s: zero on the wire %.0f ms, standstill %.0f ms, driving again %.0f ms after good scans; '%s'\n",
                bad.what.c_str(), 1e3 * (zero_at - before.t), 1e3 * (stopped.t - before.t),
                1e3 * (resumed.t - good_again.t), line.c_str());
    ros::Duration(2.0).sleep();  // back on the circle before the next one
  }

  // Scans with unusable beams among readings, and a fine scan of 100,000 beams, are used:
  // no refusal, no zero on the wire, the robot keeps driving the circle.
  const std::vector<BadScan> used = {
      {"NaN, -inf, negative and too-far beams among readings", spoiled([](sensor_msgs::LaserScan& s) {
         for (std::size_t i = 0; i < s.ranges.size(); ++i) {
           const float odd[] = {kNaNRange, -kInfRange, -1.0f, 100.0f, kInfRange};
           s.ranges[i] = odd[i % 5];
         }
       }), ""},
      {"100,000 beams over one turn", spoiled([](sensor_msgs::LaserScan& s) {
         s.angle_increment = static_cast<float>(2.0 * M_PI / 99999.0);
         s.ranges.assign(100000, kInfRange);
       }), ""},
  };
  for (const BadScan& odd : used) {
    const std::size_t since = errors.count();
    source.switchTo(odd.scan);
    const EmulatorStatus from = truth.truth();
    double slowest = 1e9;
    e2e::waitFor([&] {
      slowest = std::min(slowest, truth.truth().v);
      return false;
    }, 2.0);
    source.switchTo(goodScan());
    EXPECT_GT(slowest, 0.05) << odd.what << ": the robot slowed down or stopped";
    EXPECT_LT(e2e::firstZeroSetpoint(e2e::readCommandLog(command_log), from.t), 0.0) << odd.what << ": zero on the wire";
    EXPECT_FALSE(errors.waitForMention("scan refused", 0.2, since)) << odd.what << ": refused";
    std::printf("%s: used, slowest true speed %.3f m/s\n", odd.what.c_str(), slowest);
  }
  EXPECT_EQ(e2e::nodePid("/amigobot_manager"), manager) << "the nodelet manager died";
  RecordProperty("zero_setpoint_ms", static_cast<int>(1e3 * worst_zero));
  RecordProperty("standstill_ms", static_cast<int>(1e3 * worst_standstill));
  RecordProperty("resume_ms", static_cast<int>(1e3 * worst_resume));
}
