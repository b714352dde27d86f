// Device scan -> sensor_msgs/LaserScan: REP 117 codes, the device's angles, crop, range
// override, upside-down mount, stamps; and the parameter checks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amigobot_tracking/ros/laser_scan.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::ros_layer;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

sensors::LaserScanData urgLikeScan() {
  sensors::LaserScanData s;
  s.angle_min = -340 * 2 * M_PI / 1024;  // SCIP: (AMIN - AFRT) 2 pi / ARES
  s.angle_increment = 2 * M_PI / 1024;
  s.time_increment = 0.1 / 1024;
  s.scan_time = 0.1;
  s.range_min = 0.02;
  s.range_max = 4.0;
  for (int i = 0; i < 682; ++i) s.ranges.push_back(1.0f + 0.001f * static_cast<float>(i));
  s.ranges[0] = kInf;
  s.ranges[1] = std::numeric_limits<float>::quiet_NaN();
  s.stamp = 1000.0;
  return s;
}

}  // namespace

TEST(LaserScanConversion, KeepsTheDeviceGeometryAndCodes) {
  const sensors::LaserScanData s = urgLikeScan();
  sensor_msgs::LaserScan msg;
  LaserParams p;
  ASSERT_TRUE(toLaserScan(s, p, &msg));
  EXPECT_FLOAT_EQ(msg.angle_min, static_cast<float>(-340 * 2 * M_PI / 1024));
  EXPECT_FLOAT_EQ(msg.angle_max, static_cast<float>(341 * 2 * M_PI / 1024));  // not symmetric
  EXPECT_FLOAT_EQ(msg.angle_increment, static_cast<float>(2 * M_PI / 1024));
  EXPECT_FLOAT_EQ(msg.time_increment, static_cast<float>(0.1 / 1024));
  EXPECT_FLOAT_EQ(msg.scan_time, 0.1f);
  EXPECT_FLOAT_EQ(msg.range_max, 4.0f);
  ASSERT_EQ(msg.ranges.size(), 682u);
  EXPECT_TRUE(std::isinf(msg.ranges[0]) && msg.ranges[0] > 0);
  EXPECT_TRUE(std::isnan(msg.ranges[1]));
  EXPECT_FLOAT_EQ(msg.ranges[2], 1.002f);
  EXPECT_EQ(msg.header.frame_id, "laser");
  EXPECT_DOUBLE_EQ(msg.header.stamp.toSec(), 1000.0);
  // REP 117 layout: angle_max = angle_min + (n - 1) increment.
  EXPECT_NEAR(msg.angle_min + msg.angle_increment * (msg.ranges.size() - 1), msg.angle_max, 1e-5);
}

TEST(LaserScanConversion, CropsOverridesRangesAndShiftsTheStamp) {
  const sensors::LaserScanData s = urgLikeScan();
  LaserParams p;
  p.angle_min = -0.5;
  p.angle_max = 0.5;
  p.range_max = 1.2;
  p.range_min = 1.1;
  p.time_offset = -0.01;
  sensor_msgs::LaserScan msg;
  ASSERT_TRUE(toLaserScan(s, p, &msg));
  EXPECT_GE(msg.angle_min, -0.5f);
  EXPECT_LT(msg.angle_min - msg.angle_increment, -0.5f);
  EXPECT_LE(msg.angle_max, 0.5f);
  const int first = static_cast<int>(std::ceil((-0.5 - s.angle_min) / s.angle_increment));
  EXPECT_EQ(msg.ranges.size(), static_cast<std::size_t>(std::floor((0.5 - s.angle_min) / s.angle_increment)) - first + 1);
  EXPECT_FLOAT_EQ(msg.range_max, 1.2f);
  for (std::size_t k = 0; k < msg.ranges.size(); ++k) {
    const float device = s.ranges[static_cast<std::size_t>(first) + k];
    if (device > 1.2f) {
      EXPECT_TRUE(std::isinf(msg.ranges[k]) && msg.ranges[k] > 0) << k;
    } else if (device < 1.1f) {
      EXPECT_TRUE(std::isinf(msg.ranges[k]) && msg.ranges[k] < 0) << k;
    } else {
      EXPECT_FLOAT_EQ(msg.ranges[k], device) << k;
    }
  }
  EXPECT_NEAR(msg.header.stamp.toSec(), 1000.0 - 0.01 + first * s.time_increment, 1e-6);
  p.angle_min = 3.0;
  p.angle_max = 3.1;
  EXPECT_FALSE(toLaserScan(s, p, &msg));
}

TEST(LaserScanConversion, UpsideDownMirrorsTheBeams) {
  const sensors::LaserScanData s = urgLikeScan();
  LaserParams p;
  p.upside_down = true;
  sensor_msgs::LaserScan msg;
  ASSERT_TRUE(toLaserScan(s, p, &msg));
  EXPECT_FLOAT_EQ(msg.angle_min, static_cast<float>(-341 * 2 * M_PI / 1024));
  EXPECT_FLOAT_EQ(msg.angle_max, static_cast<float>(340 * 2 * M_PI / 1024));
  EXPECT_GT(msg.angle_increment, 0.0f);
  EXPECT_FLOAT_EQ(msg.ranges.back(), kInf);  // device beam 0 is now the last
  EXPECT_FLOAT_EQ(msg.ranges.front(), s.ranges.back());
  EXPECT_LT(msg.time_increment, 0.0f);  // the first published beam was measured last
  EXPECT_NEAR(msg.header.stamp.toSec(), 1000.0 + 681 * s.time_increment, 1e-6);
}

TEST(LaserParams, EachBadValueNamesItself) {
  auto error = [](auto change) {
    LaserParams p;
    p.driver.port = "127.0.0.1:10940";
    change(p);
    return p.validate();
  };
  EXPECT_EQ(error([](LaserParams&) {}), "");
  EXPECT_EQ(error([](LaserParams& p) { p.driver.model = "urg9"; }).rfind("model:", 0), 0u);
  EXPECT_EQ(error([](LaserParams& p) { p.driver.port = ""; }).rfind("port:", 0), 0u);
  EXPECT_EQ(error([](LaserParams& p) { p.driver.reconnect_period = -1; }).rfind("reconnect_period:", 0), 0u);
  EXPECT_EQ(error([](LaserParams& p) { p.frame_id = ""; }).rfind("frame_id:", 0), 0u);
  EXPECT_EQ(error([](LaserParams& p) { p.angle_max = -4; }).rfind("angle_max:", 0), 0u);
  EXPECT_EQ(error([](LaserParams& p) { p.range_min = -1; }).rfind("range_min:", 0), 0u);
  EXPECT_EQ(error([](LaserParams& p) { p.range_min = 2; p.range_max = 1; }).rfind("range_max:", 0), 0u);
  EXPECT_EQ(error([](LaserParams& p) { p.time_offset = NAN; }).rfind("time_offset:", 0), 0u);
}

TEST(LaserScanConversion, RplidarRosConventionTurnsTheScanByPi) {
  // An RPLIDAR revolution on the driver's grid: 360 bins over [-pi, pi); one echo at the
  // device's 0 deg mark (angle 0, bin 180) and one at +90 deg (bin 270).
  sensors::LaserScanData s;
  s.angle_min = -M_PI;
  s.angle_increment = 2 * M_PI / 360;
  s.range_min = 0.15;
  s.range_max = 12.0;
  s.ranges.assign(360, kInf);
  s.ranges[180] = 1.0f;
  s.ranges[270] = 2.0f;
  LaserParams p;
  p.driver.model = "rplidar";
  p.driver.port = "/dev/ttyUSB0";
  sensor_msgs::LaserScan device, rplidar_ros;
  ASSERT_TRUE(toLaserScan(s, p, &device));
  p.angle_convention = "rplidar_ros";
  EXPECT_EQ(p.validate(), "");
  ASSERT_TRUE(toLaserScan(s, p, &rplidar_ros));
  ASSERT_EQ(rplidar_ros.ranges.size(), 360u);
  EXPECT_FLOAT_EQ(rplidar_ros.angle_min, device.angle_min) << "the same grid";
  auto rangeAt = [](const sensor_msgs::LaserScan& m, double angle) {
    const long i = std::lround((angle - m.angle_min) / m.angle_increment);
    return m.ranges[static_cast<std::size_t>((i + 360) % 360)];
  };
  EXPECT_FLOAT_EQ(rangeAt(device, 0.0), 1.0f);
  EXPECT_FLOAT_EQ(rangeAt(rplidar_ros, M_PI), 1.0f) << "the device's 0 deg is rplidar_ros's pi";
  EXPECT_FLOAT_EQ(rangeAt(rplidar_ros, -M_PI / 2), 2.0f) << "+90 deg becomes pi - 90 deg - 2 pi";
  EXPECT_TRUE(std::isinf(rangeAt(rplidar_ros, 0.0)));

  LaserParams urg;
  urg.angle_convention = "rplidar_ros";
  EXPECT_EQ(urg.validate(), "angle_convention: rplidar_ros is for model rplidar");
}

TEST(LaserScanConversion, BaudIsTheRplidarsOnly) {
  LaserParams p;
  p.driver.model = "rplidar";
  p.driver.port = "/dev/ttyUSB0";
  p.driver.baud = 256000;
  EXPECT_EQ(p.validate(), "");
  p.driver.baud = 9600;
  EXPECT_EQ(p.validate().rfind("baud: rplidar runs at 115200 or 256000", 0), 0u) << p.validate();
  LaserParams urg;
  urg.driver.baud = 115200;
  EXPECT_EQ(urg.validate().rfind("baud: hokuyo_urg has no speed to choose", 0), 0u) << urg.validate();
}
