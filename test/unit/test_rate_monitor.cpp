// RateMonitor (ros/rate_monitor.h): FrequencyStatus's verdict merged into a node's own status
// only when the rate counts, the measured rate under the node's key. Simulated ROS time.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <ros/time.h>

#include "amigobot_tracking/ros/rate_monitor.h"

using amigobot_tracking::ros_layer::RateMonitor;
using diagnostic_msgs::DiagnosticStatus;

namespace {

std::string valueOf(const diagnostic_updater::DiagnosticStatusWrapper& s, const std::string& key) {
  for (const auto& kv : s.values) {
    if (kv.key == key) return kv.value;
  }
  return "(missing)";
}

// One diagnostic period of `ticks` events, then the report into a status that was OK.
diagnostic_updater::DiagnosticStatusWrapper period(RateMonitor* m, double* t, int ticks, bool counts) {
  for (int i = 0; i < ticks; ++i) m->tick();
  *t += 1.0;
  ros::Time::setNow(ros::Time(*t));
  diagnostic_updater::DiagnosticStatusWrapper s;
  s.summary(DiagnosticStatus::OK, "tracking");
  m->report(s, counts);
  return s;
}

}  // namespace

TEST(RateMonitor, MeasuresAndWarnsOnlyWhenItCounts) {
  double t = 100.0;
  ros::Time::init();
  ros::Time::setNow(ros::Time(t));
  RateMonitor m("control rate", "control rate measured [Hz]", 20.0, 20.0, 0.1, 1);

  auto ok = period(&m, &t, 20, true);
  EXPECT_EQ(ok.level, DiagnosticStatus::OK);
  EXPECT_EQ(ok.message, "tracking");
  EXPECT_DOUBLE_EQ(std::stod(valueOf(ok, "control rate measured [Hz]")), 20.0);
  EXPECT_EQ(valueOf(ok, "control rate: Events in window"), "20");

  auto slow = period(&m, &t, 17, true);  // 15 % low, tolerance 10 %
  EXPECT_EQ(slow.level, DiagnosticStatus::WARN);
  EXPECT_EQ(slow.message, "control rate: Frequency too low.");
  EXPECT_DOUBLE_EQ(std::stod(valueOf(slow, "control rate measured [Hz]")), 17.0);

  auto ignored = period(&m, &t, 0, false);  // e.g. cmd_vel while disabled
  EXPECT_EQ(ignored.level, DiagnosticStatus::OK);
  EXPECT_EQ(ignored.message, "tracking");
  EXPECT_DOUBLE_EQ(std::stod(valueOf(ignored, "control rate measured [Hz]")), 0.0);

  auto none = period(&m, &t, 0, true);
  EXPECT_EQ(none.level, DiagnosticStatus::ERROR);
  EXPECT_EQ(none.message, "control rate: No events recorded.");
}
