// The RPLIDAR protocol against Slamtec's description (descriptor, measurement nodes, info and
// health replies), the binning of a revolution onto the fixed grid, and the emulated
// device's conversation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amigobot_tracking/sensors/laser_session.h"
#include "amigobot_tracking/sensors/rplidar.h"

using namespace amigobot_tracking::sensors;

namespace {

std::string bytes(std::initializer_list<int> values) {
  std::string out;
  for (int v : values) out.push_back(static_cast<char>(v));
  return out;
}

}  // namespace

TEST(Rplidar, DescriptorsAsTheProtocolListsThem) {
  // SCAN: A5 5A 05 00 00 40 81 (length 5, multiple response, measurement type).
  EXPECT_EQ(rplidar::encodeDescriptor({5, true, rplidar::kMeasurementType}), bytes({0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81}));
  // GET_INFO: A5 5A 14 00 00 00 04; GET_HEALTH: A5 5A 03 00 00 00 06.
  EXPECT_EQ(rplidar::encodeDescriptor({20, false, rplidar::kInfoType}), bytes({0xA5, 0x5A, 0x14, 0x00, 0x00, 0x00, 0x04}));
  EXPECT_EQ(rplidar::encodeDescriptor({3, false, rplidar::kHealthType}), bytes({0xA5, 0x5A, 0x03, 0x00, 0x00, 0x00, 0x06}));
  rplidar::Descriptor d;
  ASSERT_EQ(rplidar::decodeDescriptor(bytes({0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81}), &d), "");
  EXPECT_EQ(d.length, 5u);
  EXPECT_TRUE(d.multiple);
  EXPECT_EQ(d.type, 0x81);
  EXPECT_NE(rplidar::decodeDescriptor(bytes({0xA5, 0x5B, 0x05, 0x00, 0x00, 0x40, 0x81}), &d), "");
  EXPECT_EQ(rplidar::request(rplidar::kGetHealth), bytes({0xA5, 0x52}));
}

TEST(Rplidar, MeasurementNodesCarryQualityStartAngleAndDistance) {
  rplidar::Node n;
  n.start = true;
  n.quality = 47;
  n.angle_q6 = 90 * 64 + 32;     // 90.5 deg
  n.distance_q2 = 1234 * 4 + 1;  // 1234.25 mm
  const std::string b = rplidar::encodeNode(n);
  ASSERT_EQ(b.size(), 5u);
  EXPECT_EQ(static_cast<std::uint8_t>(b[0]), (47 << 2) | 0x01);          // S = 1, !S = 0
  EXPECT_EQ(static_cast<std::uint8_t>(b[1]) & 0x01, 1);                  // check bit
  EXPECT_EQ(static_cast<std::uint8_t>(b[1]) >> 1, (90 * 64 + 32) & 0x7F);
  EXPECT_EQ(static_cast<std::uint8_t>(b[2]), (90 * 64 + 32) >> 7);
  rplidar::Node back;
  ASSERT_EQ(rplidar::decodeNode(reinterpret_cast<const std::uint8_t*>(b.data()), &back), "");
  EXPECT_TRUE(back.start);
  EXPECT_EQ(back.quality, 47);
  EXPECT_EQ(back.angle_q6, n.angle_q6);
  EXPECT_EQ(back.distance_q2, n.distance_q2);
  std::string bad = b;
  bad[1] = static_cast<char>(bad[1] & ~0x01);  // check bit cleared
  EXPECT_NE(rplidar::decodeNode(reinterpret_cast<const std::uint8_t*>(bad.data()), &back), "");
  bad = b;
  bad[0] = static_cast<char>(bad[0] | 0x02);  // S and !S both set
  EXPECT_NE(rplidar::decodeNode(reinterpret_cast<const std::uint8_t*>(bad.data()), &back), "");
}

TEST(Rplidar, ClockwiseDeviceAnglesBecomeRep103Angles) {
  EXPECT_NEAR(rplidar::nodeAngle(0), 0.0, 1e-12);
  EXPECT_NEAR(rplidar::nodeAngle(90 * 64), -M_PI / 2, 1e-12);  // 90 deg clockwise = to the right
  EXPECT_NEAR(rplidar::nodeAngle(270 * 64), M_PI / 2, 1e-12);
  EXPECT_NEAR(rplidar::nodeAngle(180 * 64), -M_PI, 1e-12);      // within [-pi, pi)
  for (int q : {0, 1, 5760, 11519, 11520, 11521, 23039}) EXPECT_EQ(rplidar::angleQ6(rplidar::nodeAngle(q)), q);
}

TEST(Rplidar, ARevolutionIsBinnedNearestSampleWithInfWhereNoneFell) {
  const double deg = M_PI / 180.0;
  std::vector<rplidar::Sample> samples = {{0.3 * deg, 1.0f}, {-0.2 * deg, 2.0f}, {10.6 * deg, 3.0f},
                                          {179.8 * deg, 4.0f}, {-179.9 * deg, 5.0f},
                                          {20.0 * deg, std::numeric_limits<float>::infinity()}};
  const std::vector<float> bins = rplidar::binRevolution(samples, 360);
  ASSERT_EQ(bins.size(), 360u);
  EXPECT_EQ(bins[180], 2.0f);  // 0 deg: -0.2 deg is nearer than 0.3 deg
  EXPECT_EQ(bins[191], 3.0f);  // 11 deg
  EXPECT_EQ(bins[0], 5.0f);    // -180 deg: -179.9 deg (0.1 deg away) beats 179.8 deg (0.2 deg, wrapped)
  EXPECT_TRUE(std::isinf(bins[200]));
  EXPECT_TRUE(std::isinf(bins[100]));  // no sample
}

TEST(RplidarSession, AnswersInfoHealthAndStreamsNodesAfterScan) {
  const LaserModel lidar = laserModel("rplidar");
  auto session = makeSession(lidar, "SERIAL");
  EmulatedScan scan;
  scan.ranges = {1.0f, std::numeric_limits<float>::infinity(), 2.5f};
  scan.angles = {0.0f, -0.5f, 1.0f};
  const std::string health = session->receive(rplidar::request(rplidar::kGetHealth), scan);
  EXPECT_EQ(health, bytes({0xA5, 0x5A, 0x03, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00}));
  const std::string info = session->receive("junk" + rplidar::request(rplidar::kGetInfo), scan);
  ASSERT_EQ(info.size(), 27u);
  EXPECT_EQ(rplidar::decodeInfo(info.substr(7)).model, 0x18);
  EXPECT_EQ(rplidar::decodeInfo(info.substr(7)).serial[0], 'S');
  const std::string rate = session->receive(rplidar::request(rplidar::kGetSampleRate), scan);
  ASSERT_EQ(rate.size(), 11u);
  EXPECT_EQ(static_cast<std::uint8_t>(rate[7]) | (static_cast<std::uint8_t>(rate[8]) << 8), 500);  // [us]
  EXPECT_EQ(session->stream(scan), "");
  EXPECT_EQ(session->receive(rplidar::request(rplidar::kScan), scan), bytes({0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81}));
  const std::string nodes = session->stream(scan);
  ASSERT_EQ(nodes.size(), 15u);
  rplidar::Node n;
  ASSERT_EQ(rplidar::decodeNode(reinterpret_cast<const std::uint8_t*>(nodes.data()), &n), "");
  EXPECT_TRUE(n.start);
  EXPECT_EQ(n.distance_q2, 4000);
  EXPECT_EQ(n.quality, 15);  // what an A1 sends for a measurement
  ASSERT_EQ(rplidar::decodeNode(reinterpret_cast<const std::uint8_t*>(nodes.data() + 5), &n), "");
  EXPECT_FALSE(n.start);
  EXPECT_EQ(n.distance_q2, 0);  // no echo
  EXPECT_EQ(n.quality, 0);
  EXPECT_EQ(n.angle_q6, rplidar::angleQ6(-0.5));
  EXPECT_EQ(session->receive(rplidar::request(rplidar::kStop), scan), "");  // STOP has no answer
  EXPECT_EQ(session->stream(scan), "");
  // A command with a payload (MOTOR_PWM 0xF0, 2 bytes, checksum) is skipped whole.
  EXPECT_EQ(session->receive(bytes({0xA5, 0xF0, 0x02, 0x94, 0x02, 0xC1}) + rplidar::request(rplidar::kGetHealth), scan), health);
}

TEST(RplidarSession, MotorPwmZeroStopsTheNodesUntilThePwmRestartsIt) {
  auto session = makeSession(laserModel("rplidar"), "SERIAL");
  EmulatedScan scan;
  scan.ranges = {1.0f, 2.0f};
  scan.angles = {0.0f, 1.0f};
  session->receive(rplidar::request(rplidar::kScan), scan);
  ASSERT_EQ(session->stream(scan).size(), 10u) << "spinning from power-up";
  EXPECT_EQ(session->receive(rplidar::request(rplidar::kSetMotorPwm, std::string(2, '\0')), scan), "") << "no answer";
  EXPECT_EQ(session->stream(scan), "") << "a stopped motor measures nothing";
  EXPECT_EQ(session->receive(rplidar::request(rplidar::kScan), scan).size(), rplidar::kDescriptorSize);
  EXPECT_EQ(session->stream(scan), "") << "SCAN alone does not spin the motor";
  session->receive(rplidar::request(rplidar::kSetMotorPwm, std::string{static_cast<char>(0x94), 0x02}), scan);  // 660
  EXPECT_EQ(session->stream(scan).size(), 10u);
}

TEST(Rplidar, CapsulesCarryTheirChecksumStartBitAndMillimetreDistances) {
  rplidar::Capsule in;
  in.start = true;
  in.start_angle_q6 = 1234;
  for (std::size_t i = 0; i < in.distance_mm.size(); ++i) in.distance_mm[i] = static_cast<std::uint16_t>(i * 500);
  const std::string b = rplidar::encodeCapsule(in);
  ASSERT_EQ(b.size(), 84u);
  EXPECT_EQ(static_cast<std::uint8_t>(b[0]) >> 4, 0xA);
  EXPECT_EQ(static_cast<std::uint8_t>(b[1]) >> 4, 0x5);
  EXPECT_EQ(static_cast<std::uint8_t>(b[3]) & 0x80, 0x80);  // start bit: bit 15 of the start angle
  EXPECT_EQ(static_cast<std::uint8_t>(b[9]) | (static_cast<std::uint8_t>(b[10]) << 8), 1000 << 2);  // cabin 1, distance 1
  rplidar::Capsule out;
  ASSERT_EQ(rplidar::decodeCapsule(reinterpret_cast<const std::uint8_t*>(b.data()), &out), "");
  EXPECT_TRUE(out.start);
  EXPECT_EQ(out.start_angle_q6, 1234);
  EXPECT_EQ(out.distance_mm, in.distance_mm);
  std::string bad = b;
  bad[40] ^= 0x04;
  EXPECT_EQ(rplidar::decodeCapsule(reinterpret_cast<const std::uint8_t*>(bad.data()), &out), "capsule: checksum mismatch");
}

TEST(RplidarSession, AnswersGetLidarConfPerModeAndIgnoresUnknownKeys) {
  auto session = makeSession(laserModel("rplidar"), "S");
  const EmulatedScan scan;
  auto conf = [&](std::uint32_t key, int mode) {
    std::string payload = {static_cast<char>(key & 0xFF), static_cast<char>((key >> 8) & 0xFF), 0, 0};
    if (mode >= 0) payload += std::string{static_cast<char>(mode), 0};
    return session->receive(rplidar::request(rplidar::kGetLidarConf, payload), scan);
  };
  const std::string name = conf(rplidar::kConfScanModeName, 1);
  ASSERT_EQ(name.size(), 7u + 4 + 8);  // descriptor, key, "Express\0"
  EXPECT_EQ(static_cast<std::uint8_t>(name[6]), rplidar::kLidarConfType);
  EXPECT_EQ(name.substr(11), std::string("Express") + '\0');
  const std::string type = conf(rplidar::kConfScanModeAnsType, 0);
  ASSERT_EQ(type.size(), 12u);
  EXPECT_EQ(static_cast<std::uint8_t>(type[11]), rplidar::kMeasurementType);
  EXPECT_EQ(conf(rplidar::kConfScanModeName, 5), "");  // no such mode
  EXPECT_EQ(conf(0x81, -1), "");                       // a key this firmware does not know
}
