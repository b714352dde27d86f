// Slamtec's rplidar_sdk 2.x (rplidar_ros's library) against laser_emulator over a real
// pseudo-terminal: its start-up requests replayed byte for byte and the replies parsed as
// it parses them (Slamtec/rplidar_sdk, sdk/src/sl_lidar_driver.cpp: connect's
// checkMotorCtrlSupport, getAllSupportedScanModes, startScan in standard and typical mode;
// sdk/src/dataunpacker/unpacker/handler_capsules.cpp: the capsule decoding). The SDK's code
// is not used; the real SDK was also run against the emulator once (docs/testing.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "amigobot_tracking/sensors/rplidar.h"
#include "amigobot_tracking/world/raycast.h"
#include "laser_emulator_fixture.h"
#include "raw_link.h"

using namespace amigobot_tracking;
using amigobot_test::LaserEmulator;
using amigobot_test::RawLink;
namespace rplidar = amigobot_tracking::sensors::rplidar;

namespace {

std::uint32_t le(const std::string& b, std::size_t at, int n) {
  std::uint32_t v = 0;
  for (int i = 0; i < n; ++i) v |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(b.at(at + i))) << (8 * i);
  return v;
}

std::string leBytes(std::uint32_t v, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
  return out;
}

// _sendCommandWithResponse: the descriptor (A5 5A, 30-bit length, 2-bit mode, type), then
// the payload of that length; empty when the type is not the expected one.
std::string ask(RawLink& link, const std::string& request, std::uint8_t type) {
  link.write(request);
  const std::string d = link.read(rplidar::kDescriptorSize);
  if (d.size() != rplidar::kDescriptorSize || static_cast<std::uint8_t>(d[0]) != 0xA5 || static_cast<std::uint8_t>(d[1]) != 0x5A ||
      static_cast<std::uint8_t>(d[6]) != type) {
    return "";
  }
  return link.read(le(d, 2, 4) & 0x3FFFFFFF);
}

// getLidarConf: request u32 key [+ u16 mode]; the answer repeats the key, then the value.
std::string conf(RawLink& link, std::uint32_t key, int mode = -1) {
  const std::string payload = leBytes(key, 4) + (mode >= 0 ? leBytes(static_cast<std::uint32_t>(mode), 2) : "");
  const std::string answer = ask(link, rplidar::request(rplidar::kGetLidarConf, payload), rplidar::kLidarConfType);
  if (answer.size() < 4 || le(answer, 0, 4) != key) return "\xFF";  // SL_RESULT_INVALID_DATA
  return answer.substr(4);
}

// checkSupportConfigCommands: GET_INFO; firmware >= 1.24 supports GET_LIDAR_CONF.
bool supportsConf(RawLink& link) {
  const std::string info = ask(link, rplidar::request(rplidar::kGetInfo), rplidar::kInfoType);
  return info.size() == rplidar::kInfoSize && le(info, 1, 2) >= ((1u << 8) | 24);
}

struct Mode {
  float us_per_sample = 0, max_distance = 0;
  std::uint8_t ans_type = 0;
  std::string name;
};

// The four per-mode keys startScanExpress / startScanNormal_commonpath read.
Mode readMode(RawLink& link, int id) {
  Mode m;
  const std::string us = conf(link, rplidar::kConfScanModeUsPerSample, id), dist = conf(link, rplidar::kConfScanModeMaxDistance, id);
  const std::string type = conf(link, rplidar::kConfScanModeAnsType, id), name = conf(link, rplidar::kConfScanModeName, id);
  EXPECT_EQ(us.size(), 4u);
  EXPECT_EQ(dist.size(), 4u);
  EXPECT_EQ(type.size(), 1u);
  if (us.size() == 4) m.us_per_sample = static_cast<float>(le(us, 0, 4) / 256.0);
  if (dist.size() == 4) m.max_distance = static_cast<float>(le(dist, 0, 4) >> 8);
  if (!type.empty()) m.ans_type = static_cast<std::uint8_t>(type[0]);
  m.name = name.substr(0, name.find('\0'));
  return m;
}

struct HqNode {
  bool sync;
  int angle_q6;
  int dist_q2;
};

// handler_capsules.cpp _onScanNodeCapsuleData: the previous capsule's 32 samples spread
// from its start angle to this one's (angle offsets subtracted), sync where the angle wraps.
void unpackCapsules(const std::string& bytes, std::vector<HqNode>* out) {
  bool have_previous = false;
  rplidar::Capsule previous, current;
  for (std::size_t at = 0; at + rplidar::kCapsuleSize <= bytes.size(); at += rplidar::kCapsuleSize) {
    const auto* b = reinterpret_cast<const std::uint8_t*>(bytes.data() + at);
    ASSERT_EQ(rplidar::decodeCapsule(b, &current), "") << "capsule at " << at;
    if (current.start) have_previous = false;
    if (have_previous) {
      const int current_q8 = current.start_angle_q6 << 2, previous_q8 = previous.start_angle_q6 << 2;
      int diff_q8 = current_q8 - previous_q8;
      if (previous_q8 > current_q8) diff_q8 += 360 << 8;
      const int inc_q16 = diff_q8 << 3;
      int raw_q16 = previous_q8 << 8;
      for (std::size_t k = 0; k < rplidar::kCapsuleSamples; ++k) {
        HqNode n;
        n.angle_q6 = raw_q16 >> 10;  // offsets sent as 0
        n.sync = ((raw_q16 + inc_q16) % (360 << 16)) < inc_q16;
        raw_q16 += inc_q16;
        if (n.angle_q6 >= 360 << 6) n.angle_q6 -= 360 << 6;
        n.dist_q2 = previous.distance_mm[k] << 2;
        out->push_back(n);
      }
    }
    previous = current;
    have_previous = true;
  }
}

// Each sample's distance is the ray-cast truth within 1 mm at an angle within 0.7 deg of
// the one the SDK computes (the capsule interpolation spreads the revolution's samples evenly).
int expectTruth(const std::vector<HqNode>& nodes) {
  const sensors::LaserModel device = sensors::laserModel("rplidar");
  sensors::ScanSourceOptions options;
  options.mount = amigobot_test::kMount;
  const sensors::ScanSource source(device, amigobot_test::room(), options);
  const core::Pose2 sensor = source.sensorPose(amigobot_test::kRobot);
  core::ScanGeometry ray = device.geometry();
  int checked = 0;
  for (const HqNode& n : nodes) {
    if (n.dist_q2 == 0) continue;
    const double angle = rplidar::nodeAngle(static_cast<std::uint16_t>(n.angle_q6));
    double best = std::numeric_limits<double>::infinity();
    for (int k = -45; k <= 45; ++k) {
      ray.angle_min = angle + k * M_PI / 180.0 / 64.0;
      const float truth = world::raycastScan(sensor, amigobot_test::room(), ray, 1)[0];
      if (std::isfinite(truth)) best = std::min(best, std::abs(truth - n.dist_q2 / 4000.0));
    }
    EXPECT_LT(best, 0.0011) << "angle " << n.angle_q6 / 64.0 << " deg, " << n.dist_q2 / 4.0 << " mm";
    ++checked;
  }
  return checked;
}

}  // namespace

TEST(StandardDriversRplidarSdk, ListsTheScanModesAndStreamsTheTypicalExpressMode) {
  const std::string pty = amigobot_test::ptyLink("rplidar_sdk");
  LaserEmulator emulator("rplidar", {"--pty", pty, "--tcp-port", "-1"});
  RawLink link(pty);
  // connect: checkMotorCtrlSupport's GET_INFO (an A1, major id 1: no accessory board query).
  const std::string info = ask(link, rplidar::request(rplidar::kGetInfo), rplidar::kInfoType);
  ASSERT_EQ(info.size(), 20u);
  EXPECT_EQ(static_cast<std::uint8_t>(info[0]) >> 4, 1);
  EXPECT_EQ(ask(link, rplidar::request(rplidar::kGetHealth), rplidar::kHealthType), std::string(3, '\0'));
  // getAllSupportedScanModes.
  ASSERT_TRUE(supportsConf(link));
  const std::string count = conf(link, rplidar::kConfScanModeCount);
  ASSERT_EQ(count.size(), 2u);
  ASSERT_EQ(le(count, 0, 2), 2u);
  const Mode standard = readMode(link, 0), express = readMode(link, 1);
  EXPECT_EQ(standard.name, "Standard");
  EXPECT_EQ(standard.ans_type, rplidar::kMeasurementType);
  EXPECT_EQ(express.name, "Express");
  EXPECT_EQ(express.ans_type, rplidar::kCapsuledType);
  EXPECT_FLOAT_EQ(standard.us_per_sample, 500.0f);
  EXPECT_FLOAT_EQ(standard.max_distance, 12.0f);
  // startScan(false, true): STOP, GET_INFO, typical mode, then startScanExpress: STOP,
  // GET_INFO, the four per-mode keys, EXPRESS_SCAN {working_mode, flags, param}.
  link.write(rplidar::request(rplidar::kStop));
  ASSERT_TRUE(supportsConf(link));
  const std::string typical = conf(link, rplidar::kConfScanModeTypical);
  ASSERT_EQ(typical.size(), 2u);
  const int mode = static_cast<int>(le(typical, 0, 2));
  EXPECT_EQ(mode, 1);
  link.write(rplidar::request(rplidar::kStop));
  ASSERT_TRUE(supportsConf(link));
  EXPECT_EQ(readMode(link, mode).ans_type, rplidar::kCapsuledType);
  // startMotor -> setMotorSpeed -> getDesiredSpeed: the SDK reads 4 bytes of the answer
  // without checking its size (an empty answer crashed it), rpm then PWM reference.
  const std::string speed = conf(link, rplidar::kConfDesiredRotFreq);
  ASSERT_EQ(speed.size(), 4u);
  EXPECT_EQ(le(speed, 0, 2), 330u);  // 5.5 Hz
  link.write(rplidar::request(rplidar::kExpressScan, std::string(1, static_cast<char>(mode)) + std::string(4, '\0')));
  const std::string d = link.read(rplidar::kDescriptorSize);
  rplidar::Descriptor descriptor;
  ASSERT_EQ(rplidar::decodeDescriptor(d, &descriptor), "");
  EXPECT_EQ(descriptor.type, rplidar::kCapsuledType);
  EXPECT_EQ(descriptor.length, 84u);
  EXPECT_TRUE(descriptor.multiple);
  const std::string capsules = link.read(84 * 40, 6.0);  // ~3.5 revolutions of ~363 samples
  ASSERT_EQ(capsules.size(), 84u * 40);
  EXPECT_TRUE(capsules[3] & 0x80);  // the first capsule after the request carries the start bit
  std::vector<HqNode> nodes;
  unpackCapsules(capsules, &nodes);
  ASSERT_EQ(nodes.size(), 39u * 32);
  int revolutions = 0;
  std::size_t last_sync = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i].sync) continue;
    if (revolutions++ > 0) {
      EXPECT_NEAR(static_cast<double>(i - last_sync), 2000.0 / 5.5, 12.0);  // samples per turn
    }
    last_sync = i;
  }
  EXPECT_GE(revolutions, 3);
  EXPECT_GT(expectTruth(nodes), 200);
}

TEST(StandardDriversRplidarSdk, StandardModeStreamsNodesWithTheQualityOfAnA1) {
  const std::string pty = amigobot_test::ptyLink("rplidar_sdk_std");
  LaserEmulator emulator("rplidar", {"--pty", pty, "--tcp-port", "-1"});
  RawLink link(pty);
  // startScan(false, false): STOP, GET_INFO, the four keys of mode 0, SCAN.
  link.write(rplidar::request(rplidar::kStop));
  ASSERT_TRUE(supportsConf(link));
  const Mode standard = readMode(link, 0);
  EXPECT_EQ(standard.ans_type, rplidar::kMeasurementType);
  link.write(rplidar::request(rplidar::kScan));
  rplidar::Descriptor descriptor;
  ASSERT_EQ(rplidar::decodeDescriptor(link.read(rplidar::kDescriptorSize), &descriptor), "");
  EXPECT_EQ(descriptor.type, rplidar::kMeasurementType);
  const std::string bytes = link.read(5 * 800, 6.0);
  ASSERT_EQ(bytes.size(), 5u * 800);
  int measured = 0, starts = 0;
  for (std::size_t at = 0; at < bytes.size(); at += 5) {
    rplidar::Node n;
    ASSERT_EQ(rplidar::decodeNode(reinterpret_cast<const std::uint8_t*>(bytes.data() + at), &n), "");
    EXPECT_EQ(n.quality, n.distance_q2 > 0 ? 15 : 0);
    measured += n.distance_q2 > 0;
    starts += n.start;
  }
  EXPECT_GT(measured, 200);
  EXPECT_GE(starts, 2);
}
