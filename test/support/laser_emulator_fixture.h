// Test helper for the laser driver against the laser_emulator executable: a room (disks, a wall, a table)
// as a world file, the emulator as a child process (robot at a fixed pose), polling the
// driver for scans and comparing them with the ray-cast truth at the device's geometry.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "amigobot_tracking/sensors/laser_driver.h"
#include "amigobot_tracking/sensors/scan_source.h"
#include "amigobot_tracking/world/world.h"
#include "child_process.h"

namespace amigobot_test {

using amigobot_tracking::core::Disk;
using amigobot_tracking::core::Pose2;
namespace sensors = amigobot_tracking::sensors;

const Pose2 kRobot{0.5, -0.2, 0.3};
const Pose2 kMount{0.11, 0.02, 0.1};

// Disks, a wall to the right and a triangular table ahead-left.
inline amigobot_tracking::world::World room() {
  amigobot_tracking::world::World room;
  for (const auto& d : {std::array<double, 3>{2.0, 0.0, 0.3}, {0.0, 2.5, 0.5}, {-1.0, -1.0, 0.2}, {6.0, 3.0, 1.0}}) {
    Disk disk;
    disk.center = {d[0], d[1]};
    disk.radius = d[2];
    room.obstacles.push_back(disk);
  }
  room.walls.push_back({{-3.0, -2.0}, {4.0, -2.0}});
  room.polygons.push_back({{{2.5, 1.0}, {3.0, 1.0}, {3.0, 1.6}}});
  return room;
}

inline std::string worldFile() {
  const std::string path = "/tmp/amigobot_laser_test_world_" + std::to_string(::getpid()) + ".yaml";
  std::ofstream(path) << amigobot_tracking::world::worldYaml(room());
  return path;
}

class LaserEmulator {
 public:
  explicit LaserEmulator(const std::string& model, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {AMIGOBOT_LASER_EMULATOR, "--model", model, "--tcp-port", "0", "--world", worldFile(),
                                     "--pose", std::to_string(kRobot.x), std::to_string(kRobot.y), std::to_string(kRobot.theta),
                                     "--mount-x", std::to_string(kMount.x), "--mount-y", std::to_string(kMount.y),
                                     "--mount-yaw", std::to_string(kMount.theta)};
    args.insert(args.end(), extra.begin(), extra.end());
    const std::string line = process_.start(args);
    char pty[256] = {0};
    if (std::sscanf(line.c_str(), "READY tcp=%d pty=%255s", &port_, pty) != 2) {
      throw std::runtime_error("laser_emulator did not start: '" + line + "'");
    }
  }
  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }

 private:
  ChildProcess process_;
  int port_ = -1;
};

inline std::string ptyLink(const std::string& name) { return "/tmp/amigobot_" + name + "_" + std::to_string(::getpid()); }

inline sensors::LaserDriverConfig driverConfig(const std::string& model, const std::string& port) {
  sensors::LaserDriverConfig c;
  c.model = model;
  c.port = port;
  c.reconnect_period = 0.2;
  return c;
}

// Polls until `count` scans arrived or `timeout` [s] passed; returns the last one.
inline sensors::LaserScanData scans(sensors::LaserDriver& driver, int count, double timeout) {
  sensors::LaserScanData scan, last;
  int got = 0;
  const double end = sensors::systemSeconds() + timeout;
  while (got < count && sensors::systemSeconds() < end) {
    if (driver.poll(&scan, 0.2)) {
      EXPECT_GE(scan.stamp, last.stamp) << "stamps must not go back";
      last = scan;
      ++got;
    }
  }
  EXPECT_EQ(got, count) << "last error: " << driver.lastError();
  return last;
}

// Every beam equals the ray-cast truth within the protocol's 1 mm quantisation, at the
// device's own geometry.
inline void expectTruth(const sensors::LaserModel& device, const sensors::LaserScanData& scan) {
  sensors::ScanSourceOptions options;
  options.mount = kMount;
  sensors::ScanSource source(device, room(), options);
  const sensors::EmulatedScan truth = source.cast(kRobot, 0.0);
  ASSERT_EQ(scan.ranges.size(), truth.ranges.size());
  EXPECT_NEAR(scan.angle_min, device.angleMin(), 1e-9);
  EXPECT_NEAR(scan.angle_increment, device.angleIncrement(), 1e-9);
  EXPECT_NEAR(scan.scan_time, device.scanTime(), 1e-9);
  EXPECT_NEAR(scan.range_max, device.range_max, 1e-9);
  int finite = 0;
  for (std::size_t i = 0; i < truth.ranges.size(); ++i) {
    if (!std::isfinite(truth.ranges[i])) {
      EXPECT_TRUE(std::isinf(scan.ranges[i]) && scan.ranges[i] > 0) << "beam " << i;
    } else {
      EXPECT_NEAR(scan.ranges[i], truth.ranges[i], 0.0005 + 1e-6) << "beam " << i;
      ++finite;
    }
  }
  EXPECT_GT(finite, 50);  // the room is in view
}

inline void expectTruth(const std::string& model, const sensors::LaserScanData& scan) {
  expectTruth(sensors::laserModel(model), scan);
}

}  // namespace amigobot_test
