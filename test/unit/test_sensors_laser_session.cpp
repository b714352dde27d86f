// The emulated devices' conversations: what a driver sends, what the device answers, and
// that the streamed ranges decode to the ray-cast truth at the device's own geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amigobot_tracking/sensors/cola_a.h"
#include "amigobot_tracking/sensors/laser_session.h"
#include "amigobot_tracking/sensors/scan_source.h"
#include "amigobot_tracking/sensors/scip.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::sensors;

namespace {

EmulatedScan rampScan(int beams) {
  EmulatedScan scan;
  for (int i = 0; i < beams; ++i) scan.ranges.push_back(0.5f + 0.001f * static_cast<float>(i));
  scan.ranges[3] = std::numeric_limits<float>::infinity();
  scan.ranges[4] = std::numeric_limits<float>::quiet_NaN();
  scan.t = 12.345;
  return scan;
}

// The ranges of a SCIP data reply: data lines without their sum characters.
std::vector<std::uint32_t> scipRanges(const std::string& reply) {
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < reply.size();) {
    const std::size_t end = reply.find('\n', at);
    lines.push_back(reply.substr(at, end - at));
    at = end + 1;
  }
  std::string data;
  for (std::size_t i = 3; i < lines.size() && !lines[i].empty(); ++i) {
    EXPECT_EQ(lines[i].back(), scip::checksum(lines[i].substr(0, lines[i].size() - 1)));
    data += lines[i].substr(0, lines[i].size() - 1);
  }
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i + 3 <= data.size(); i += 3) out.push_back(scip::decode(data.substr(i, 3)));
  return out;
}

}  // namespace

TEST(LaserModel, DeviceGeometryComesFromTheProtocolNumbers) {
  const LaserModel urg = laserModel("hokuyo_urg");
  EXPECT_EQ(urg.beams(), 682);
  EXPECT_DOUBLE_EQ(urg.angleMin(), -340 * 2 * M_PI / 1024);  // (AMIN - AFRT) 2 pi / ARES
  EXPECT_DOUBLE_EQ(urg.angleMax(), 341 * 2 * M_PI / 1024);   // not symmetric: AMAX - AFRT = 341
  EXPECT_DOUBLE_EQ(urg.rate, 10.0);
  EXPECT_DOUBLE_EQ(urg.range_max, 4.0);
  const LaserModel tim = laserModel("sick_tim5xx");
  EXPECT_EQ(tim.beams(), 811);
  EXPECT_NEAR(tim.angleMin(), -135.0 * M_PI / 180, 1e-12);
  EXPECT_NEAR(tim.angleIncrement(), 0.3333 * M_PI / 180, 1e-12);
  EXPECT_DOUBLE_EQ(tim.rate, 15.0);
  EXPECT_THROW(laserModel("lidar9000"), std::invalid_argument);
}

TEST(ScipSession, AnswersWhatMrptsDriverSendsAndStreamsScans) {
  const LaserModel urg = laserModel("hokuyo_urg");
  auto session = makeSession(urg, "H1");
  const EmulatedScan scan = rampScan(urg.beams());
  EXPECT_EQ(session->receive("QT\n", scan), "QT\n00P\n\n");
  EXPECT_EQ(session->receive("SCIP2.0\nBM\n", scan), "SCIP2.0\n00P\n\nBM\n00P\n\n");
  const std::string pp = session->receive("PP\n", scan);
  EXPECT_NE(pp.find("\nAMIN:44;7\n"), std::string::npos) << pp;
  EXPECT_NE(pp.find("\nARES:1024;\\\n"), std::string::npos);
  EXPECT_NE(pp.find("\nAFRT:384;6\n"), std::string::npos);
  EXPECT_EQ(session->stream(scan), "");  // nothing asked yet
  EXPECT_EQ(session->receive("MD0044072501000\n", scan), "MD0044072501000\n00P\n\n");
  const std::string data = session->stream(scan);
  ASSERT_EQ(data.rfind("MD0044072501000\n99b\n", 0), 0u) << data.substr(0, 40);
  EXPECT_EQ(data.substr(data.size() - 2), "\n\n");
  EXPECT_EQ(scip::decode(data.substr(20, 4)), 12345u);  // time stamp [ms]
  const std::vector<std::uint32_t> ranges = scipRanges(data);
  ASSERT_EQ(ranges.size(), 682u);
  EXPECT_EQ(ranges[0], 500u);
  EXPECT_EQ(ranges[681], 1181u);
  EXPECT_EQ(ranges[3], 0u);  // no echo
  EXPECT_EQ(ranges[4], 1u);  // dropout
  EXPECT_EQ(session->receive("XX\n", scan), "XX\n0Ee\n\n");  // unknown command: status 0E, sum (0x30 + 0x45) & 0x3F + 0x30
  session->receive("QT\n", scan);
  EXPECT_EQ(session->stream(scan), "");
}

TEST(ScipSession, SingleScanRequestsAndClusters) {
  const LaserModel urg = laserModel("hokuyo_urg");
  auto session = makeSession(urg, "H1");
  const EmulatedScan scan = rampScan(urg.beams());
  EXPECT_EQ(session->receive("GD0044004601\n", scan).substr(0, 17), "GD0044004601\n02R\n");  // laser off
  session->receive("BM\n", scan);
  const std::string reply = session->receive("GD0044005502\n", scan);
  ASSERT_EQ(reply.rfind("GD0044005502\n00P\n", 0), 0u);
  const std::vector<std::uint32_t> ranges = scipRanges(reply);
  ASSERT_EQ(ranges.size(), 6u);  // steps 44..55 in pairs
  EXPECT_EQ(ranges[0], 500u);
  EXPECT_EQ(ranges[1], 502u);  // beams 2 and 3: the one measured range (beam 3 has no echo)
}

TEST(ColaSession, AnswersPollsAndStreamsWhenAsked) {
  const LaserModel tim = laserModel("sick_tim5xx");
  auto session = makeSession(tim, "12345678");
  const EmulatedScan scan = rampScan(tim.beams());
  EXPECT_EQ(session->receive(cola::frame("sMN SetAccessMode 03 F4724744"), scan), cola::frame("sAN SetAccessMode 1"));
  EXPECT_EQ(session->receive(cola::frame("sRN SerialNumber"), scan), cola::frame("sRA SerialNumber 8 12345678"));
  EXPECT_EQ(session->receive(cola::frame("sXX nonsense"), scan), cola::frame("sFA 2"));
  std::string buffer = session->receive(cola::frame("sRN LMDscandata"), scan), body;
  ASSERT_TRUE(cola::nextTelegram(&buffer, &body));
  cola::ScanTelegram telegram;
  ASSERT_EQ(cola::decodeScan(body, &telegram), "");
  EXPECT_EQ(telegram.command, "sRA");
  ASSERT_EQ(telegram.ranges.size(), 811u);
  EXPECT_EQ(telegram.ranges[0], 500u);
  EXPECT_EQ(telegram.ranges[3], 0u);
  EXPECT_EQ(telegram.ranges[4], 0u);
  EXPECT_EQ(telegram.start_angle, -450000);
  EXPECT_EQ(telegram.scan_frequency, 1500u);
  EXPECT_EQ(telegram.time_since_start_us, 12345000u);
  EXPECT_EQ(session->stream(scan), "");
  EXPECT_EQ(session->receive(cola::frame("sEN LMDscandata 1"), scan), cola::frame("sEA LMDscandata 1"));
  buffer = session->stream(scan);
  ASSERT_TRUE(cola::nextTelegram(&buffer, &body));
  EXPECT_EQ(body.substr(0, 15), "sSN LMDscandata");
}

TEST(ScanSource, CastsFromTheMountPoseAndUpsideDownMirrors) {
  const LaserModel tim = laserModel("sick_tim5xx");
  core::Disk wall;
  wall.center = {3.0, 1.0};
  wall.radius = 0.5;
  ScanSourceOptions options;
  options.mount = {0.11, 0.0, 0.0};
  ScanSource source(tim, world::disksOnly({wall}), options);
  const core::Pose2 base{0.0, 1.0, 0.0};
  const EmulatedScan scan = source.cast(base, 1.0);
  const std::size_t front = 405;  // -135 deg + 405 * 0.3333 deg = -0.0135 deg
  EXPECT_NEAR(scan.ranges[front], 3.0 - 0.5 - 0.11, 1e-3);
  options.upside_down = true;
  ScanSource mirrored(tim, world::disksOnly({wall}), options);
  EXPECT_NEAR(mirrored.cast(base, 1.0).ranges[front], scan.ranges[front], 1e-3);
  options.dropout = 2.0;
  EXPECT_THROW(ScanSource(tim, world::World{}, options), std::invalid_argument);
}

TEST(ScanSource, SeesAPersonWhereItIsAtTheScansEmulatorTime) {
  // A person walks across the beam straight ahead (x = 2 m) at 0.5 m/s, on it at t = 10 s.
  world::Person person;
  person.radius = 0.25;
  person.motion.start = {2.0, -5.0};
  person.motion.legs = {{20.0, {0.0, 0.5}}};
  world::World room;
  room.people = {person};
  ScanSource source(laserModel("sick_tim5xx"), room, ScanSourceOptions{});
  const std::size_t front = 405;  // -0.0135 deg
  EXPECT_NEAR(source.cast({0.0, 0.0, 0.0}, 10.0).ranges[front], 1.75, 1e-3);
  EXPECT_FALSE(std::isfinite(source.cast({0.0, 0.0, 0.0}, 2.0).ranges[front])) << "still 4 m south of the beam";
}

TEST(ColaSession, Lms1xxNeedsTheClientLoginToMeasureAndReportsItsConfiguration) {
  const LaserModel lms = laserModel("sick_lms1xx");
  EXPECT_EQ(lms.beams(), 541);
  EXPECT_NEAR(lms.angleMin(), -135.0 * M_PI / 180, 1e-12);
  EXPECT_DOUBLE_EQ(lms.rate, 25.0);
  auto session = makeSession(lms, "LMS1");
  const EmulatedScan scan = rampScan(lms.beams());
  auto ask = [&](const std::string& body) { return session->receive(cola::frame(body), scan); };
  EXPECT_EQ(ask("sRN LMPscancfg"), cola::frame("sRA LMPscancfg 9C4 1 1388 FFF92230 225510"));  // 25 Hz, 0.5 deg, -45..225 deg
  EXPECT_EQ(ask("sRN STlms").substr(0, 12), cola::frame("sRA STlms 3").substr(0, 12));           // idle
  EXPECT_EQ(ask("sMN LMCstartmeas"), cola::frame("sFA 1"));                                    // not logged in
  EXPECT_EQ(ask("sMN SetAccessMode 03 00000000"), cola::frame("sAN SetAccessMode 0"));           // wrong password
  EXPECT_EQ(ask("sMN SetAccessMode 03 F4724744"), cola::frame("sAN SetAccessMode 1"));
  EXPECT_EQ(ask("sEN LMDscandata 1"), cola::frame("sEA LMDscandata 1"));
  EXPECT_EQ(session->stream(scan), "");  // enabled, but not measuring yet
  EXPECT_EQ(ask("sMN LMCstartmeas"), cola::frame("sAN LMCstartmeas 0"));
  EXPECT_EQ(ask("sMN Run"), cola::frame("sAN Run 1"));
  // Ready for measurement at the first query: clearpath's LMS1xx_node asks once right after
  // LMCstartmeas and reconnects otherwise.
  EXPECT_EQ(ask("sRN STlms").substr(0, 12), cola::frame("sRA STlms 7").substr(0, 12));
  std::string buffer = session->stream(scan), body;
  ASSERT_TRUE(cola::nextTelegram(&buffer, &body));
  cola::ScanTelegram telegram;
  ASSERT_EQ(cola::decodeScan(body, &telegram), "");
  EXPECT_EQ(telegram.ranges.size(), 541u);
  EXPECT_EQ(telegram.angular_step, 5000u);
  EXPECT_EQ(telegram.scan_frequency, 2500u);
  EXPECT_EQ(telegram.measurement_frequency, 180u);  // 720 beams per turn at 25 Hz, in 100 Hz
}

TEST(ColaSession, AnswersTheOutputRangeAndTheScanDataConfigurationAsTheDeviceDoes) {
  const LaserModel tim = laserModel("sick_tim5xx");
  auto session = makeSession(tim, "TIM1");
  const EmulatedScan scan = rampScan(tim.beams());
  auto ask = [&](const std::string& body) { return session->receive(cola::frame(body), scan); };
  // The TiM's output range as sick_scan's start-up log shows a real one: 0.3333 deg, -45 .. 225 deg.
  EXPECT_EQ(ask("sRN LMPoutputRange"), cola::frame("sRA LMPoutputRange 1 D05 FFF92230 225510"));
  EXPECT_EQ(ask("sWN LMPoutputRange 1 D05 FFF92230 225510"), cola::frame("sWA LMPoutputRange"));
  EXPECT_EQ(ask("sWN LMDscandatacfg 01"), cola::frame("sFA 3"));  // too few parameters
  // Remission at 8-bit resolution: RSSI1 among the 8-bit channels, one value per beam.
  EXPECT_EQ(ask("sWN LMDscandatacfg 01 00 1 0 0 00 00 0 0 0 0 +1"), cola::frame("sWA LMDscandatacfg"));
  ask("sEN LMDscandata 1");
  std::string buffer = session->stream(scan), body;
  ASSERT_TRUE(cola::nextTelegram(&buffer, &body));
  EXPECT_NE(body.find(" 0 1 DIST1 "), std::string::npos);
  cola::ScanTelegram telegram;
  ASSERT_EQ(cola::decodeScan(body, &telegram), "");
  ASSERT_EQ(telegram.rssi.size(), telegram.ranges.size());
  for (std::size_t i = 0; i < telegram.ranges.size(); ++i) {
    EXPECT_EQ(telegram.rssi[i] == 0, telegram.ranges[i] == 0) << i;  // no echo, no remission
    EXPECT_LE(telegram.rssi[i], 255u);
  }
}
