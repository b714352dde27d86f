// The start-up and streaming conversations of the standard ROS drivers, replayed request
// for request against laser_emulator over a real TCP socket, each reply checked as that
// driver parses it. The request sequences and the parsing are read from the drivers' public
// sources (cited per test); their code is not used. The real drivers, built from those
// sources, were also run against the emulator once (docs/testing.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <sstream>
#include <vector>

#include "amigobot_tracking/sensors/scip.h"
#include "laser_emulator_fixture.h"
#include "raw_link.h"

using amigobot_test::LaserEmulator;
using amigobot_test::RawLink;
namespace scip = amigobot_tracking::sensors::scip;

namespace {

// urg_c's scip_response() (ros-drivers/urg_c, current/src/urg_sensor.c): the echo must
// start with the command, every later line ends with the sum of the line without its last
// one or two characters, the status line has 3 characters; returns the lines counted
// (line_number - 1: echo, status, data lines and the empty line) and the lines after the echo.
int scipResponse(RawLink& link, const std::string& command, std::vector<std::string>* lines) {
  link.write(command);
  lines->clear();
  int line_number = 0;
  for (;;) {
    std::string line = link.readUntil('\n');
    if (line.empty()) return -1;  // URG_NO_RESPONSE
    line.pop_back();
    const std::size_t n = line.size();
    if (line_number == 0) {
      if (line.compare(0, command.size() - 1, command, 0, command.size() - 1) != 0) return -2;  // URG_INVALID_RESPONSE
    } else if (n > 0) {
      const char sum = line[n - 1];
      if (sum != scip::checksum(line.substr(0, n - 1)) && (n < 2 || sum != scip::checksum(line.substr(0, n - 2)))) return -3;
      lines->push_back(line);
    }
    if (line_number == 1 && n != 3) return -2;
    ++line_number;
    if (n == 0) return line_number - 1;
  }
}

// urg_c's copy_token(): the text after `start` up to the first of the `end` characters
// (each tried in turn over all lines); "" when none is found (urg_c: RECEIVE_ERROR_MESSAGE).
std::string copyToken(const std::vector<std::string>& lines, const std::string& start, const std::string& end) {
  for (char e : end) {
    for (const std::string& l : lines) {
      if (l.compare(0, start.size(), start) != 0) continue;
      const std::size_t at = l.find(e, start.size());
      if (at != std::string::npos) return l.substr(start.size(), at - start.size());
    }
  }
  return "";
}

std::string framed(const std::string& body) { return "\x02" + body + "\x03"; }

// One reply telegram without STX/ETX, as LMS1xx::read() gets it after one request.
std::string colaAsk(RawLink& link, const std::string& body) {
  link.write(framed(body));
  std::string reply = link.readUntil('\x03');
  if (reply.size() < 2 || reply[0] != '\x02') return "";
  return reply.substr(1, reply.size() - 2);
}

std::vector<std::string> tokens(const std::string& body) {
  std::istringstream in(body);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

unsigned hexField(const std::string& t) { return static_cast<unsigned>(std::stoul(t, nullptr, 16)); }

}  // namespace

// urg_node's start-up through urg_c: urg_open (QT, then PP: 10 lines), the identity
// queries urg_node logs (urg_sensor_product_type / serial_id / vendor / firmware_version /
// firmware_date / protocol_version: VV, 7 lines; urg_sensor_status / state: II, 9 lines),
// then urg_start_measurement (BM, then MD) and the scans.
TEST(StandardDriversUrgC, OpensQueriesTheIdentityAndStatusAndStreams) {
  LaserEmulator emulator("hokuyo_urg");
  RawLink link(emulator.address());
  std::vector<std::string> lines;
  ASSERT_EQ(scipResponse(link, "QT\n", &lines), 2);
  EXPECT_EQ(lines[0], "00P");  // connect_urg_device: "00P" means SCIP 2.0 already
  ASSERT_GE(scipResponse(link, "PP\n", &lines), 10);  // PP_RESPONSE_LINES
  EXPECT_EQ(std::strtol(copyToken(lines, "AMIN:", ";").c_str(), nullptr, 10), 44);
  EXPECT_EQ(std::strtol(copyToken(lines, "DMAX:", ";").c_str(), nullptr, 10), 4000);
  ASSERT_GE(scipResponse(link, "VV\n", &lines), 7);  // VV_RESPONSE_LINES
  EXPECT_EQ(copyToken(lines, "PROD:", ";"), "SOKUIKI Sensor URG-04LX (emulated)");
  EXPECT_EQ(copyToken(lines, "SERI:", ";"), "H0000001");
  EXPECT_EQ(copyToken(lines, "VEND:", ";"), "Hokuyo Automatic Co.,Ltd.");
  const std::string firmware = copyToken(lines, "FIRM:", "(");  // urg_sensor_firmware_version
  EXPECT_EQ(firmware, "3.4.03");
  // urg_sensor_firmware_date: FIRM up to ';', then what follows "version(" up to ')'.
  const std::string firm = copyToken(lines, "FIRM:", ";");
  EXPECT_EQ(copyToken({firm}, firmware + "(", ")"), "17/Dec./2012");
  EXPECT_EQ(copyToken(lines, "PROT:", ";"), "SCIP 2.0");
  ASSERT_GE(scipResponse(link, "II\n", &lines), 9);  // II_RESPONSE_LINES
  EXPECT_EQ(copyToken(lines, "STAT:", ";"), "Sensor works well.");  // urg_sensor_status
  EXPECT_EQ(copyToken(lines, "MESM:", " ("), "Idling");             // urg_sensor_state: laser off
  ASSERT_EQ(scipResponse(link, "BM\n", &lines), 2);
  ASSERT_GE(scipResponse(link, "II\n", &lines), 9);
  EXPECT_EQ(copyToken(lines, "MESM:", " ("), "Measuring");
  EXPECT_EQ(copyToken(lines, "LASR:", ";"), "ON");
  // urg_start_measurement(URG_DISTANCE, 0, 0): "MD" first last cluster(2) skip(1) times(2).
  ASSERT_EQ(scipResponse(link, "MD0044072501000\n", &lines), 2);
  EXPECT_EQ(lines[0], "00P");
  for (int scan = 0; scan < 3; ++scan) {  // each scan: echo, "99b", stamp, data lines, empty
    const std::string echo = link.readUntil('\n');
    ASSERT_EQ(echo, "MD0044072501000\n") << "scan " << scan;
    EXPECT_EQ(link.readUntil('\n'), "99b\n");
    std::size_t chars = 0;
    for (std::string line = link.readUntil('\n'); line.size() > 1; line = link.readUntil('\n')) {
      line.pop_back();
      EXPECT_EQ(line.back(), scip::checksum(line.substr(0, line.size() - 1)));
      chars += line.size() - 1;
    }
    EXPECT_EQ(chars, 4 + 682 * 3u);  // time stamp + 682 steps of 3 characters
  }
}

// clearpath's LMS1xx_node (clearpathrobotics/LMS1xx, src/LMS1xx_node.cpp connect_lidar and
// start_measurements; src/LMS1xx.cpp the telegrams and their sscanf formats): login,
// LMPscancfg, LMPoutputRange, LMDscandatacfg with remission, LMCstartmeas, one STlms that
// must be 7, Run, sEN LMDscandata 1; then each scan through parseScanData().
TEST(StandardDriversLms1xx, ClearpathStartUpReachesReadyOnOneConnectionAndParsesTheScans) {
  LaserEmulator emulator("sick_lms1xx");
  RawLink link(emulator.address());
  EXPECT_EQ(colaAsk(link, "sMN SetAccessMode 03 F4724744"), "sAN SetAccessMode 1");
  unsigned frequency = 0, resolution = 0, start = 0, stop = 0;
  ASSERT_EQ(std::sscanf(colaAsk(link, "sRN LMPscancfg").c_str(), "%*s %*s %X %*d %X %X %X", &frequency, &resolution, &start, &stop), 4);
  EXPECT_EQ(frequency, 2500u);
  unsigned out_resolution = 0, out_start = 0, out_stop = 0;
  const std::string range = colaAsk(link, "sRN LMPoutputRange");
  EXPECT_EQ(range.rfind("sRA LMPoutputRange ", 0), 0u) << range;
  ASSERT_EQ(std::sscanf(range.c_str(), "%*s %*s %*d %X %X %X", &out_resolution, &out_start, &out_stop), 3);
  EXPECT_EQ(out_resolution, 5000u);
  EXPECT_EQ(static_cast<int>(out_start), -450000);
  EXPECT_EQ(static_cast<int>(out_stop), 2250000);
  const int num_values = static_cast<int>(out_stop - out_start) / static_cast<int>(out_resolution) + 1;  // construct_scan
  EXPECT_EQ(colaAsk(link, "sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 0 +1"), "sWA LMDscandatacfg");
  EXPECT_EQ(colaAsk(link, "sMN LMCstartmeas"), "sAN LMCstartmeas 0");
  const std::string status = "\x02" + colaAsk(link, "sRN STlms");
  int stat = -1;
  ASSERT_EQ(std::sscanf(status.c_str() + 10, "%d", &stat), 1);  // queryStatus: buf + 10
  EXPECT_EQ(stat, 7) << status;                                   // ready_for_measurement
  EXPECT_EQ(colaAsk(link, "sMN Run"), "sAN Run 1");
  EXPECT_EQ(colaAsk(link, "sEN LMDscandata 1"), "sEA LMDscandata 1");
  for (int scan = 0; scan < 3; ++scan) {
    std::string body = link.readUntil('\x03');
    ASSERT_GT(body.size(), 2u) << "scan " << scan;
    body = body.substr(1, body.size() - 2);
    const std::vector<std::string> t = tokens(body);
    ASSERT_GT(t.size(), 30u);
    std::size_t at = 18;  // parseScanData: 18 header tokens, then NumberEncoders
    const int encoders = std::stoi(t[at++]);
    at += 2 * static_cast<std::size_t>(encoders);
    int dist_len = -1, rssi_len = -1;
    for (int block = 0; block < 2; ++block) {  // 16-bit channels, then 8-bit channels
      const int channels = std::stoi(t.at(at++));
      for (int c = 0; c < channels; ++c) {
        const std::string content = t.at(at);
        const int count = static_cast<int>(hexField(t.at(at + 5)));
        (content == "DIST1" ? dist_len : rssi_len) = count;
        if (content == "DIST1") {
          EXPECT_EQ(t.at(at + 1), "3F800000");  // scale factor 1
        }
        at += 6 + static_cast<std::size_t>(count);
      }
    }
    EXPECT_EQ(dist_len, num_values);
    EXPECT_EQ(rssi_len, num_values);  // remission asked for: RSSI1 sent
    EXPECT_LE(at + 5, t.size());      // position, name, comment, time, event follow
  }
}

// sick_tim's start-up (uos/sick_tim, src/sick_tim_common.cpp init_scanner: sRI0,
// SerialNumber, FirmwareVersion, SCdevicestate compared with "sRA SCdevicestate 1",
// sEN LMDscandata 1) and its parser's checks (src/sick_tim551_2050001_parser.cpp: at least
// 26 + 1 + 5 fields, field 15 "0", field 20 "DIST1", 1..811 data, the RSSI flag after the
// data, scan time from field 16, time increment from field 17).
TEST(StandardDriversSickTim, StartUpAndTheParsersFieldChecks) {
  LaserEmulator emulator("sick_tim5xx");
  RawLink link(emulator.address());
  EXPECT_EQ(colaAsk(link, "sRI0").rfind("sRA", 0), 0u);
  EXPECT_EQ(colaAsk(link, "sRN SerialNumber").rfind("sRA SerialNumber", 0), 0u);
  EXPECT_EQ(colaAsk(link, "sRN FirmwareVersion").rfind("sRA FirmwareVersion", 0), 0u);
  EXPECT_EQ(colaAsk(link, "sRN SCdevicestate"), "sRA SCdevicestate 1");
  EXPECT_EQ(colaAsk(link, "sEN LMDscandata 1"), "sEA LMDscandata 1");
  std::string body = link.readUntil('\x03');
  ASSERT_GT(body.size(), 2u);
  const std::vector<std::string> f = tokens(body.substr(1, body.size() - 2));
  ASSERT_GE(f.size(), 26u + 1 + 5);
  EXPECT_EQ(f[0], "sSN");
  EXPECT_EQ(f[15], "0");
  EXPECT_EQ(f[20], "DIST1");
  const unsigned data = hexField(f[25]);
  EXPECT_EQ(data, 811u);
  ASSERT_GE(f.size(), 26 + data + 1 + 5);
  EXPECT_EQ(f[26 + data], "0");  // no RSSI
  EXPECT_NEAR(1.0 / (hexField(f[16]) / 100.0), 1.0 / 15.0, 1e-9);
}
