// CoLa-A fields and the LMDscandata telegram against SICK's telegram listing.
#include <gtest/gtest.h>

#include "amigobot_tracking/sensors/cola_a.h"
#include "real_cola_telegrams.h"

using namespace amigobot_tracking::sensors;

TEST(ColaA, HexFieldsAsTheListingWritesThem) {
  EXPECT_EQ(cola::hex(5000), "1388");         // scan frequency 50 Hz in 1/100 Hz
  EXPECT_EQ(cola::hex(1500), "5DC");          // 15 Hz
  EXPECT_EQ(cola::hex(3333), "D05");          // 0.3333 deg in 1/10000 deg
  EXPECT_EQ(cola::hex(811), "32B");           // beams of a TiM5xx
  EXPECT_EQ(cola::hexSigned(-450000), "FFF92230");  // starting angle -45 deg
  EXPECT_EQ(cola::hex(0), "0");
  EXPECT_EQ(cola::parseHex("FFF92230", "angle"), 0xFFF92230u);
  EXPECT_EQ(static_cast<std::int32_t>(cola::parseHex("FFF92230", "angle")), -450000);
  EXPECT_THROW(cola::parseHex("12G", "range"), std::invalid_argument);
  EXPECT_THROW(cola::parseHex("", "range"), std::invalid_argument);
}

TEST(ColaA, TelegramsAreFramedAndFoundInAStream) {
  EXPECT_EQ(cola::frame("sRN LMDscandata"), "\x02sRN LMDscandata\x03");
  std::string buffer = "noise\x02sRN SerialNumber\x03\x02sMN Run\x03\x02sRN Fi";
  std::string body;
  ASSERT_TRUE(cola::nextTelegram(&buffer, &body));
  EXPECT_EQ(body, "sRN SerialNumber");
  ASSERT_TRUE(cola::nextTelegram(&buffer, &body));
  EXPECT_EQ(body, "sMN Run");
  EXPECT_FALSE(cola::nextTelegram(&buffer, &body));
  EXPECT_EQ(buffer, "\x02sRN Fi");  // the incomplete telegram waits for its ETX
  buffer += "\x02sMN Run\x03";      // a cut telegram followed by a whole one: the whole one
  ASSERT_TRUE(cola::nextTelegram(&buffer, &body));
  EXPECT_EQ(body, "sMN Run");
}

TEST(ColaA, DecodesAHandWrittenScanTelegram) {
  const std::string body =
      "sRA LMDscandata 1 1 89A27F 0 0 343 347 27477BA9 2747813B 0 0 7 0 0 5DC A2 0 1 DIST1 3F800000 00000000 "
      "FFF92230 D05 3 3E8 0 FA0 0 0 0 0 0 0";
  cola::ScanTelegram scan;
  ASSERT_EQ(cola::decodeScan(body, &scan), "");
  EXPECT_EQ(scan.command, "sRA");
  EXPECT_EQ(scan.serial, 0x89A27Fu);
  EXPECT_EQ(scan.telegram_counter, 0x343u);
  EXPECT_EQ(scan.scan_counter, 0x347u);
  EXPECT_EQ(scan.scan_frequency, 1500u);
  EXPECT_EQ(scan.measurement_frequency, 162u);
  EXPECT_FLOAT_EQ(scan.scale_factor, 1.0f);
  EXPECT_EQ(scan.start_angle, -450000);
  EXPECT_EQ(scan.angular_step, 3333u);
  EXPECT_EQ(scan.ranges, (std::vector<std::uint32_t>{1000, 0, 4000}));
}

TEST(ColaA, EncodeThenDecodeKeepsEveryField) {
  cola::ScanTelegram in;
  in.command = "sSN";
  in.serial = 0x1234567;
  in.telegram_counter = 7;
  in.scan_counter = 9;
  in.time_since_start_us = 123456789;
  in.time_of_transmission_us = 123500000;
  in.scan_frequency = 1500;
  in.measurement_frequency = 162;
  in.start_angle = -450000;
  in.angular_step = 3333;
  in.ranges = {1, 2, 0xFFFF, 0};
  const std::string body = cola::encodeScan(in);
  EXPECT_NE(body.find(" DIST1 3F800000 0 FFF92230 D05 4 1 2 FFFF 0 "), std::string::npos) << body;
  cola::ScanTelegram out;
  ASSERT_EQ(cola::decodeScan(body, &out), "");
  EXPECT_EQ(out.command, in.command);
  EXPECT_EQ(out.time_since_start_us, in.time_since_start_us);
  EXPECT_EQ(out.start_angle, in.start_angle);
  EXPECT_EQ(out.ranges, in.ranges);
}

TEST(ColaA, RejectsBrokenScanTelegrams) {
  cola::ScanTelegram scan;
  const std::string good =
      "sRA LMDscandata 1 1 1 0 0 1 1 1 1 0 0 0 0 0 5DC A2 0 1 DIST1 3F800000 0 FFF92230 D05 3 1 2 3 0 0 0 0 0 0";
  ASSERT_EQ(cola::decodeScan(good, &scan), "");
  EXPECT_NE(cola::decodeScan(good.substr(0, good.find(" 2 3 ")), &scan), "");  // truncated
  std::string bad = good;
  bad.replace(bad.find(" 2 3 "), 5, " Z 3 ");
  EXPECT_NE(cola::decodeScan(bad, &scan).find("range"), std::string::npos);
  EXPECT_NE(cola::decodeScan("sRA SerialNumber 8 12345678", &scan), "");
}

// Real telegrams, read field by field as clearpath's LMS1xx::parseScanData (src/LMS1xx.cpp:
// encoder count, then per encoder position and speed, then the 16-bit and 8-bit channel
// blocks, each channel by its name) and sick_tim's parser (field 20 DIST1, RSSI after the
// data) read them.
TEST(ColaA, DecodesARealTelegramWithAnEncoderBlockAndAn8BitRssiChannel) {
  cola::ScanTelegram scan;
  ASSERT_EQ(cola::decodeScan(amigobot_test::kLms5xxEncoderTelegram, &scan), "");
  EXPECT_EQ(scan.serial, 0x1160456u);
  EXPECT_EQ(scan.telegram_counter, 0x9506u);
  EXPECT_EQ(scan.scan_counter, 0x951Eu);
  EXPECT_EQ(scan.time_since_start_us, 0x36B9861Eu);
  EXPECT_EQ(scan.scan_frequency, 5000u);         // 50 Hz
  EXPECT_EQ(scan.measurement_frequency, 0x21Cu);
  EXPECT_EQ(scan.encoder_positions, std::vector<std::uint32_t>{0u});
  EXPECT_EQ(scan.encoder_speeds, std::vector<std::uint32_t>{0u});
  EXPECT_FLOAT_EQ(scan.scale_factor, 1.0f);
  EXPECT_FLOAT_EQ(scan.scale_offset, 0.0f);
  EXPECT_EQ(scan.start_angle, -48333);  // FFFF4333
  EXPECT_EQ(scan.angular_step, 3333u);
  ASSERT_EQ(scan.ranges.size(), 570u);  // 23A
  EXPECT_EQ(scan.ranges.front(), 0x981u);
  EXPECT_EQ(scan.ranges[1], 0x97Cu);
  EXPECT_EQ(scan.ranges.back(), 0x1770u);
  ASSERT_EQ(scan.rssi.size(), 570u);
  EXPECT_EQ(scan.rssi.front(), 0xFEu);
  EXPECT_EQ(scan.rssi.back(), 0xBBu);
}

TEST(ColaA, DecodesARealTelegramWithDistAndRssiAs16BitChannels) {
  cola::ScanTelegram scan;
  ASSERT_EQ(cola::decodeScan(amigobot_test::kTim5xxDistRssiTelegram, &scan), "");
  EXPECT_EQ(scan.serial, 0x1078AAAu);
  EXPECT_EQ(scan.scan_frequency, 1500u);
  EXPECT_TRUE(scan.encoder_positions.empty());
  EXPECT_EQ(scan.start_angle, -450000);
  EXPECT_EQ(scan.angular_step, 3333u);
  ASSERT_EQ(scan.ranges.size(), 811u);
  EXPECT_EQ(scan.ranges[0], 0u);
  EXPECT_EQ(scan.ranges[2], 0xD12u);
  EXPECT_EQ(scan.ranges.back(), 0x2CDu);
  ASSERT_EQ(scan.rssi.size(), 811u);
  EXPECT_EQ(scan.rssi[2], 0xD93u);
}

// The telegram listing allows any channel order and a scale factor offset; SICK's own
// sick_scan reads DIST1 wherever it is (and the LMS5xx sends scale factor 2.0 at times).
TEST(ColaA, FindsDist1AfterRssi1AndAppliesScaleFactorAndOffset) {
  const std::string body =
      "sSN LMDscandata 1 1 1 0 0 1 1 1 1 0 0 0 0 0 5DC A2 2 10 20 30 40 2 "
      "RSSI1 3F800000 0 FFF92230 D05 3 FE FD FC "
      "DIST1 40000000 41200000 FFF92230 D05 3 1F4 0 3E8 "
      "1 DIST2 3F800000 0 FFF92230 D05 3 1 2 3 0 0 0 0 0";
  cola::ScanTelegram scan;
  ASSERT_EQ(cola::decodeScan(body, &scan), "");
  EXPECT_EQ(scan.encoder_positions, (std::vector<std::uint32_t>{0x10, 0x30}));
  EXPECT_EQ(scan.encoder_speeds, (std::vector<std::uint32_t>{0x20, 0x40}));
  EXPECT_EQ(scan.ranges, (std::vector<std::uint32_t>{500, 0, 1000}));  // DIST1, not RSSI1 or DIST2
  EXPECT_EQ(scan.rssi, (std::vector<std::uint32_t>{0xFE, 0xFD, 0xFC}));
  EXPECT_FLOAT_EQ(scan.scale_factor, 2.0f);
  EXPECT_FLOAT_EQ(scan.scale_offset, 10.0f);
  // No DIST1 at all, or an encoder block that runs past the end: refused, naming it.
  std::string no_dist = body;
  no_dist.replace(no_dist.find("DIST1"), 5, "DIST3");
  EXPECT_EQ(cola::decodeScan(no_dist, &scan), "scan telegram: no DIST1 channel");
  EXPECT_NE(cola::decodeScan("sSN LMDscandata 1 1 1 0 0 1 1 1 1 0 0 0 0 0 5DC A2 9 1 2", &scan).find("encoder"),
            std::string::npos);
}

TEST(ColaA, EncodesRssiWhereTheConfigurationAskedForIt) {
  cola::ScanTelegram in;
  in.angular_step = 5000;
  in.start_angle = -450000;
  in.ranges = {1000, 0};
  in.rssi = {200, 0};
  for (bool eight : {false, true}) {
    in.rssi_8bit = eight;
    const std::string body = cola::encodeScan(in);
    EXPECT_NE(body.find(eight ? " 0 1 DIST1 " : " 0 2 DIST1 "), std::string::npos) << body;
    EXPECT_NE(body.find(eight ? " 3E8 0 1 RSSI1 " : " 3E8 0 RSSI1 "), std::string::npos) << body;
    cola::ScanTelegram out;
    ASSERT_EQ(cola::decodeScan(body, &out), "");
    EXPECT_EQ(out.ranges, in.ranges);
    EXPECT_EQ(out.rssi, in.rssi);
  }
}

// Issue 25: these gave a "fresh" scan with every range dropped (blind but driving).
TEST(ColaA, AnInvalidGeometryIsAnErrorNamingTheField) {
  const std::string good =
      "sRA LMDscandata 1 1 1 0 0 1 1 1 1 0 0 0 0 0 5DC A2 0 1 DIST1 3F800000 0 FFF92230 D05 3 1 2 3 0 0 0 0 0 0";
  auto with = [&](const std::string& from, const std::string& to) {
    std::string body = good;
    body.replace(body.find(from), from.size(), to);
    cola::ScanTelegram scan;
    return cola::decodeScan(body, &scan);
  };
  EXPECT_NE(with(" 3F800000 ", " 7FC00000 ").find("scale factor"), std::string::npos);  // NaN
  EXPECT_NE(with(" 3F800000 ", " 0 ").find("scale factor"), std::string::npos);         // 0
  EXPECT_NE(with(" 3F800000 ", " BF800000 ").find("scale factor"), std::string::npos);  // -1
  EXPECT_NE(with(" 3F800000 ", " 7F800000 ").find("scale factor"), std::string::npos);  // +inf
  EXPECT_NE(with(" D05 3 ", " 0 3 ").find("angular step"), std::string::npos);
  EXPECT_NE(with(" D05 3 ", " 36EE81 3 ").find("angular step"), std::string::npos);  // 360.0001 deg
  EXPECT_NE(with(" D05 3 ", " 1E8480 3 ").find("span more than 360"), std::string::npos);  // 3 beams, 200 deg apart
  EXPECT_EQ(with(" D05 3 ", " 1B7740 3 "), "");  // 3 beams 180 deg apart: 0..360 deg, usable
  EXPECT_NE(with(" FFF92230 ", " 7FFFFFFF ").find("starting angle"), std::string::npos);
  cola::ScanTelegram kept;
  kept.scan_counter = 42;
  const std::string nan_body = good.substr(0, good.find(" 3F800000 ")) + " 7FC00000" +
                               good.substr(good.find(" 3F800000 ") + 9);
  EXPECT_NE(cola::decodeScan(nan_body, &kept), "");
  EXPECT_EQ(kept.scan_counter, 42u) << "a refused telegram leaves *scan as it was";
}
