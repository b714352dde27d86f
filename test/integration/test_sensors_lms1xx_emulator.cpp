// The CoLa-A driver for the SICK LMS1xx against laser_emulator over a real socket: the login,
// scan configuration and start-up conversation of the telegram listing, every beam equal to
// the ray-cast truth within the 1 mm quantisation at the configured geometry (0.5 deg at
// 25 or 50 Hz, 0.25 deg at 25 Hz), and the faults survived.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/sensors/cola_protocol.h"  // setLms1xxScanConfig: an LMS1xx (CoLa-A) setting
#include "laser_emulator_fixture.h"

using namespace amigobot_tracking::sensors;
using amigobot_test::LaserEmulator;
using amigobot_test::driverConfig;
using amigobot_test::expectTruth;
using amigobot_test::scans;

TEST(Lms1xxDriver, LogsInReadsTheScanConfigurationAndGivesTheRayCastTruth) {
  LaserEmulator emulator("sick_lms1xx");
  LaserDriver driver(driverConfig("sick_lms1xx", emulator.address()));
  const LaserScanData scan = scans(driver, 3, 10.0);
  expectTruth("sick_lms1xx", scan);
  EXPECT_EQ(scan.ranges.size(), 541u);
  EXPECT_NEAR(scan.angle_min, -135.0 * M_PI / 180.0, 1e-9);
  EXPECT_NEAR(scan.angleMax(), 135.0 * M_PI / 180.0, 1e-9);
  EXPECT_NEAR(scan.angle_increment, 0.5 * M_PI / 180.0, 1e-9);
  EXPECT_NEAR(scan.scan_time, 0.04, 1e-9);
  EXPECT_NEAR(scan.time_increment, 0.04 / 720, 1e-7);  // 0.5 deg of a 25 Hz turn
  EXPECT_DOUBLE_EQ(scan.range_min, 0.01);  // as clearpath's LMS1xx driver: real echoes from 0.126 m
  EXPECT_DOUBLE_EQ(scan.range_max, 20.0);
  const std::string id = driver.identity();
  EXPECT_NE(id.find("LMS111"), std::string::npos) << id;
  EXPECT_NE(id.find("scan configuration 25 Hz, 0.5 deg, -45 .. 225 deg"), std::string::npos) << id;
}

TEST(Lms1xxDriver, TakesTheOtherScanConfigurationsFromTheDevice) {
  for (const auto& cfg : {std::pair<const char*, const char*>{"25", "0.25"}, {"50", "0.5"}}) {
    LaserEmulator emulator("sick_lms1xx", {"--scan-frequency", cfg.first, "--resolution", cfg.second});
    LaserDriver driver(driverConfig("sick_lms1xx", emulator.address()));
    LaserModel device = laserModel("sick_lms1xx");
    setLms1xxScanConfig(&device, std::stod(cfg.first), std::stod(cfg.second));
    const LaserScanData scan = scans(driver, 5, 10.0);
    expectTruth(device, scan);
    EXPECT_EQ(scan.ranges.size(), std::string(cfg.second) == "0.25" ? 1081u : 541u) << cfg.first;
    EXPECT_NEAR(scan.scan_time, 1.0 / std::stod(cfg.first), 1e-9);
  }
}

TEST(Lms1xxDriver, SkipsDamagedScansAndReopensAfterADisconnect) {
  for (const char* fault : {"malformed", "truncated"}) {
    LaserEmulator emulator("sick_lms1xx", {"--fault", fault, "--fault-every", "4"});
    LaserDriver driver(driverConfig("sick_lms1xx", emulator.address()));
    expectTruth("sick_lms1xx", scans(driver, 12, 10.0));
    EXPECT_EQ(driver.counters().opens, 1u) << fault;
    if (std::string(fault) == "malformed") {
      EXPECT_GE(driver.counters().damaged, 1u);
    }
  }
  LaserEmulator emulator("sick_lms1xx", {"--fault", "disconnect", "--fault-every", "10"});
  LaserDriver driver(driverConfig("sick_lms1xx", emulator.address()));
  expectTruth("sick_lms1xx", scans(driver, 25, 20.0));
  EXPECT_GE(driver.counters().opens, 2u);  // logged in and started again
}

TEST(Lms1xxDriver, RefusesASerialPortAndAnUnknownConfiguration) {
  LaserDriverConfig c = driverConfig("sick_lms1xx", "/dev/ttyUSB0");
  EXPECT_THROW(c.validate(), std::invalid_argument);
  LaserModel m = laserModel("sick_lms1xx");
  EXPECT_THROW(setLms1xxScanConfig(&m, 50.0, 0.25), std::invalid_argument);
  EXPECT_THROW(setLms1xxScanConfig(&m, 35.0, 0.5), std::invalid_argument);
}
