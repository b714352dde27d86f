// The laser model registry (sensors/laser_registry.h): every entry complete and consistent,
// and an unknown model an error wherever a model is named (model, session, driver, emulator),
// naming it and the known ones; the emulator's endpoint and scan options read from the entry.
#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/sensors/laser_emulator_server.h"
#include "amigobot_tracking/sensors/laser_protocol.h"
#include "amigobot_tracking/sensors/laser_registry.h"

using namespace amigobot_tracking::sensors;

namespace {

template <typename F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LaserRegistry, EveryEntryIsCompleteAndItsModelCarriesItsName) {
  ASSERT_GE(laserModels().size(), 4u);
  for (const LaserModelEntry& e : laserModels()) {
    SCOPED_TRACE(e.name);
    ASSERT_TRUE(e.model);
    ASSERT_NE(e.model().protocol, nullptr);
    EXPECT_FALSE(e.description.empty());
    const LaserModel m = e.model();
    EXPECT_EQ(m.name, e.name);
    EXPECT_GT(m.beams(), 1);
    EXPECT_GT(m.rate, 0.0);
    EXPECT_GT(m.range_max, m.range_min);
    EXPECT_GT(m.range_min, 0.0);
    EXPECT_TRUE(e.bauds.empty() || e.serial()) << "bauds without a serial link";
    EXPECT_NE(makeSession(m, "S1"), nullptr);
    EXPECT_EQ(&laserModelEntry(e.name), &e);
    EXPECT_NE(laserModelList().find(e.name), std::string::npos);
  }
}

TEST(LaserRegistry, UnknownModelIsAnErrorEverywhereNamingItAndTheKnownOnes) {
  const std::string known = laserModelList();
  const auto expectNamed = [&](const std::string& error) {
    EXPECT_NE(error.find("'lidar9000'"), std::string::npos) << error;
    EXPECT_NE(error.find(known), std::string::npos) << error;
  };
  expectNamed(errorOf([] { laserModel("lidar9000"); }));
  LaserModel stray = laserModel("hokuyo_urg");
  stray.name = "lidar9000";
  expectNamed(errorOf([&] { makeSession(stray, "S1"); }));
  LaserDriverConfig config;
  config.model = "lidar9000";
  const std::string driver_error = errorOf([&] { config.validate(); });
  EXPECT_EQ(driver_error.rfind("model:", 0), 0u) << driver_error;
  EXPECT_NE(driver_error.find("lidar9000"), std::string::npos) << driver_error;
  EXPECT_NE(amigobot_tracking::core::checkFields(laserDriverFields(), config), "");
}

TEST(LaserRegistry, LinksAndBaudsComeFromTheEntry) {
  LaserDriverConfig c;
  c.model = "sick_tim5xx";
  c.port = "/dev/ttyUSB0";
  EXPECT_NE(errorOf([&] { c.validate(); }).find("TCP only"), std::string::npos);
  c.model = "rplidar";
  c.port = "localhost:2111";
  EXPECT_NE(errorOf([&] { c.validate(); }).find("serial device"), std::string::npos);
  c.port = "/dev/ttyUSB0";
  c.baud = 256000;
  EXPECT_EQ(errorOf([&] { c.validate(); }), "");
  c.port = "localhost:99999";
  EXPECT_NE(errorOf([&] { c.validate(); }).find("'localhost:99999'"), std::string::npos);
  LaserServerOptions pty;
  pty.pty_link = "/tmp/never";
  EXPECT_NE(errorOf([&] { pty.validate(laserModel("sick_lms1xx")); }).find("sick_lms1xx has no serial port"), std::string::npos);
  EXPECT_EQ(errorOf([&] { pty.validate(laserModel("hokuyo_urg")); }), "");
}

// The emulator's endpoint comes from the entry's link (serial-only: a pty; else TCP), so the
// launch file passes a port alone and the driver's laser_emulator:PORT opens the same place.
TEST(LaserRegistry, EmulatorEndpointFollowsTheEntrysLink) {
  for (const LaserModelEntry& e : laserModels()) {
    SCOPED_TRACE(e.name);
    const LaserEndpoint endpoint = laserEmulatorEndpoint(e.name, 10940);
    if (e.tcp()) {
      EXPECT_EQ(endpoint.tcp_port, 10940);
      EXPECT_EQ(endpoint.pty, "");
      EXPECT_EQ(endpoint.address(), "localhost:10940");
    } else {
      EXPECT_EQ(endpoint.tcp_port, -1);
      EXPECT_EQ(endpoint.pty, "/tmp/amigobot_laser_" + e.name + "_10940");
      EXPECT_EQ(endpoint.address(), endpoint.pty);
    }
    EXPECT_EQ(resolveLaserPort(e.name, "laser_emulator:10940"), endpoint.address());
    LaserDriverConfig c;
    c.model = e.name;
    c.port = "laser_emulator:10940";
    EXPECT_EQ(errorOf([&] { c.validate(); }), "") << "the endpoint is always the model's own link";
  }
  EXPECT_EQ(laserEmulatorEndpoint("rplidar", 10940).address(), "/tmp/amigobot_laser_rplidar_10940");
  EXPECT_EQ(laserEmulatorEndpoint("sick_lms1xx", 10940).address(), "localhost:10940");
  EXPECT_EQ(resolveLaserPort("rplidar", "/dev/ttyUSB0"), "/dev/ttyUSB0");  // other ports as they are
  EXPECT_EQ(resolveLaserPort("sick_tim5xx", "192.168.0.1:2112"), "192.168.0.1:2112");
  const std::string unknown = errorOf([] { laserEmulatorEndpoint("lidar9000", 10940); });
  EXPECT_NE(unknown.find("'lidar9000'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find(laserModelList()), std::string::npos) << unknown;
  EXPECT_NE(errorOf([] { resolveLaserPort("lidar9000", "laser_emulator:10940"); }).find("'lidar9000'"), std::string::npos);
  EXPECT_NE(errorOf([] { laserEmulatorEndpoint("rplidar", 0); }).find("port 0"), std::string::npos);
  LaserDriverConfig bad;
  bad.model = "rplidar";
  bad.port = "laser_emulator:x";
  EXPECT_EQ(errorOf([&] { bad.validate(); }).rfind("port:", 0), 0u);
}

// --scan-frequency / --resolution are the entry's scan setting: a model without one refuses
// them, naming the option and the model; a model with one applies them.
TEST(LaserRegistry, EmulatorScanOptionsNeedTheEntrysScanSetting) {
  const std::string tim = errorOf([] { emulatedLaserModel("sick_tim5xx", 25.0, std::nullopt); });
  EXPECT_NE(tim.find("--scan-frequency"), std::string::npos) << tim;
  EXPECT_NE(tim.find("sick_tim5xx"), std::string::npos) << tim;
  EXPECT_NE(tim.find("sick_lms1xx"), std::string::npos) << tim << " (the models that take it)";
  const std::string urg = errorOf([] { emulatedLaserModel("hokuyo_urg", std::nullopt, 0.5); });
  EXPECT_NE(urg.find("--resolution"), std::string::npos) << urg;
  EXPECT_NE(urg.find("hokuyo_urg"), std::string::npos) << urg;
  EXPECT_NE(errorOf([] { emulatedLaserModel("lidar9000", std::nullopt, std::nullopt); }).find("'lidar9000'"),
            std::string::npos);
  for (const LaserModelEntry& e : laserModels()) {
    SCOPED_TRACE(e.name);
    EXPECT_EQ(emulatedLaserModel(e.name, std::nullopt, std::nullopt).beams(), e.model().beams());
    if (e.scan_setting) {
      EXPECT_NE(scanSettingChoices().find(e.name), std::string::npos);
    }
  }
  const LaserModel fast = emulatedLaserModel("sick_lms1xx", 50.0, std::nullopt);
  EXPECT_EQ(fast.rate, 50.0);
  EXPECT_EQ(emulatedLaserModel("sick_lms1xx", std::nullopt, 0.25).beams(), 1081);
  EXPECT_NE(errorOf([] { emulatedLaserModel("sick_lms1xx", 50.0, 0.25); }).find("25 Hz"), std::string::npos);
}

// Each model's protocol (laser_protocol.h) says what the emulator, the driver and the node
// offer for it, so none of them names a protocol: the RPLIDAR alone turns a motor, samples
// as it turns and has rplidar_ros's angles; SCIP alone carries a checksum.
TEST(LaserRegistry, EachModelsProtocolSaysWhatItOffers) {
  for (const LaserModelEntry& e : laserModels()) {
    SCOPED_TRACE(e.name);
    const LaserProtocol& p = protocolOf(e.model());
    const bool rplidar = e.name == "rplidar", scip = e.name == "hokuyo_urg";
    EXPECT_EQ(p.hasMotor(), rplidar);
    EXPECT_EQ(p.samplesAsItTurns(), rplidar);
    EXPECT_EQ(p.rosDriverAngleConvention(), rplidar ? "rplidar_ros" : "");
    EXPECT_EQ(p.hasChecksum(), scip);
    EXPECT_EQ(p.noMeasurementCode(-1.0f / 0.0f), scip ? 1u : 0u);  // -inf: too close
    EXPECT_EQ(p.noMeasurementCode(1.0f / 0.0f), 0u);                // +inf: nothing within range
  }
}

TEST(LaserRegistry, AChecksumFaultNamesTheModelsWhoseProtocolHasOne) {
  LaserServerOptions options;
  options.fault = Fault::kChecksum;
  options.fault_every = 3;
  EXPECT_NO_THROW(options.validate(laserModel("hokuyo_urg")));
  const std::string error = errorOf([&] { options.validate(laserModel("sick_tim5xx")); });
  EXPECT_EQ(error, "fault: checksum needs a model whose protocol has a checksum (hokuyo_urg); sick_tim5xx speaks CoLa-A, which has none");
  EXPECT_NE(errorOf([&] { options.validate(laserModel("rplidar")); }).find("rplidar speaks RPLIDAR"), std::string::npos);
}

TEST(LaserRegistry, AModelBuiltWithoutItsEntryHasNoProtocolAndSaysSo) {
  LaserModel bare;
  bare.name = "bare";
  EXPECT_NE(errorOf([&] { bare.beams(); }).find("laser model 'bare': no protocol"), std::string::npos);
}
