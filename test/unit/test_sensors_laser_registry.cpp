// The laser model registry (sensors/laser_registry.h): every entry complete and consistent,
// and an unknown model an error wherever a model is named (model, session, driver, emulator),
// naming it and the known ones.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "amigobot_tracking/core/field_table.h"
#include "amigobot_tracking/sensors/laser_emulator_server.h"
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
    ASSERT_TRUE(e.model && e.open && e.session);
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
