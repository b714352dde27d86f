// SCIP 2.0 encoders against the specification's examples and a URG-04LX's own replies.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "amigobot_tracking/sensors/scip.h"

using namespace amigobot_tracking::sensors;

TEST(Scip, ChecksumsOfStatusLines) {
  EXPECT_EQ(scip::checksum("00"), 'P');  // 0x30 + 0x30 = 0x60; & 0x3F = 0x20; + 0x30 = 'P'
  EXPECT_EQ(scip::checksum("99"), 'b');
  EXPECT_EQ(scip::statusLine("00"), "00P");
}

TEST(Scip, ChecksumsOfParameterLinesCoverTheTextBeforeTheSemicolon) {
  // Lines of a URG-04LX's VV and PP replies, with the sum character the device sends.
  EXPECT_EQ(scip::checksum("VEND:Hokuyo Automatic Co.,Ltd."), '[');
  EXPECT_EQ(scip::checksum("PROT:SCIP 2.0"), 'N');
  EXPECT_EQ(scip::checksum("DMIN:20"), '4');
  EXPECT_EQ(scip::checksum("DMAX:5600"), '_');
  EXPECT_EQ(scip::checksum("ARES:1024"), '\\');
  EXPECT_EQ(scip::checksum("AMIN:44"), '7');
  EXPECT_EQ(scip::checksum("AMAX:725"), 'o');
  EXPECT_EQ(scip::checksum("AFRT:384"), '6');
  EXPECT_EQ(scip::checksum("SCAN:600"), 'e');
}

TEST(Scip, EncodingsOfTheSpecificationExamples) {
  EXPECT_EQ(scip::encode(1234, 2), "CB");      // 2-character encoding
  EXPECT_EQ(scip::encode(5432, 3), "1Dh");     // 3-character encoding
  EXPECT_EQ(scip::encode(16000000, 4), "m2@0");  // 4-character encoding (time stamps)
  EXPECT_EQ(scip::decode("CB"), 1234u);
  EXPECT_EQ(scip::decode("1Dh"), 5432u);
  EXPECT_EQ(scip::decode("m2@0"), 16000000u);
  EXPECT_EQ(scip::encode(0, 3), "000");
}

TEST(Scip, EncodingRejectsWhatDoesNotFit) {
  EXPECT_THROW(scip::encode(4096, 2), std::out_of_range);  // 2 characters hold 12 bits
  EXPECT_EQ(scip::encode(4095, 2), "oo");
  EXPECT_THROW(scip::decode("0~"), std::invalid_argument);
}

TEST(Scip, RepliesAreEchoStatusDataAndAnEmptyLine) {
  EXPECT_EQ(scip::reply("BM", "00"), "BM\n00P\n\n");
  EXPECT_EQ(scip::infoReply("PP", {"AMIN:44", "AFRT:384"}), "PP\n00P\nAMIN:44;7\nAFRT:384;6\n\n");
}

TEST(Scip, ScanRepliesCutDataIntoLinesOf64Characters) {
  const std::vector<std::uint32_t> ranges(30, 5432);  // 90 characters: 64 + 26
  const std::string reply = scip::scanReply("MD0044007301000", "99", 16000000, ranges, 3);
  std::string line64, line26;
  for (int i = 0; i < 21; ++i) line64 += "1Dh";
  line64 += "1";
  line26 = "Dh";
  for (int i = 0; i < 8; ++i) line26 += "1Dh";
  const std::string expected = "MD0044007301000\n99b\nm2@0" + std::string(1, scip::checksum("m2@0")) + "\n" + line64 +
                               scip::checksum(line64) + "\n" + line26 + scip::checksum(line26) + "\n\n";
  EXPECT_EQ(reply, expected);
  EXPECT_EQ(line64.size(), 64u);
  EXPECT_EQ(line26.size(), 26u);
}

TEST(Scip, ScanRequestsAreParsedAndChecked) {
  scip::ScanRequest r;
  ASSERT_EQ(scip::parseScanRequest("MD0044072501000", &r), "");
  EXPECT_EQ(r.start, 44);
  EXPECT_EQ(r.end, 725);
  EXPECT_EQ(r.cluster, 1);
  EXPECT_EQ(r.interval, 0);
  EXPECT_EQ(r.count, 0);
  EXPECT_TRUE(r.continuous());
  EXPECT_EQ(r.encodingChars(), 3);
  ASSERT_EQ(scip::parseScanRequest("GS0100020003", &r), "");
  EXPECT_FALSE(r.continuous());
  EXPECT_EQ(r.encodingChars(), 2);
  EXPECT_EQ(r.cluster, 3);
  EXPECT_NE(scip::parseScanRequest("MD00440725010", &r), "");   // too short
  EXPECT_NE(scip::parseScanRequest("MD0725004401000", &r), "");  // start after end
  EXPECT_NE(scip::parseScanRequest("MD00x4072501000", &r), "");
  EXPECT_NE(scip::parseScanRequest("VV", &r), "");
}

TEST(Scip, ReplySumCheckFindsAWrongSumInAStreamReadInPieces) {
  const std::string good = scip::scanReply("MD0044004801000", "99", 1234, {500, 600, 0, 1, 4000}, 3);
  scip::ReplySumCheck check;
  const std::string info = scip::infoReply("VV", {"VEND:Hokuyo Automatic Co.,Ltd.", "SERI:H0000001"});
  const std::string stream = scip::reply("BM", "00") + info + good + good;
  for (std::size_t at = 0; at < stream.size(); at += 7) check.feed(stream.data() + at, std::min<std::size_t>(7, stream.size() - at));
  EXPECT_EQ(check.badLines(), 0u);
  std::string bad = good;
  bad[bad.size() - 3] ^= 0x01;  // the last data line's sum, as laser_emulator --fault checksum
  check.feed(bad.data(), bad.size());
  EXPECT_EQ(check.badLines(), 1u);
  EXPECT_EQ(check.lastBad().back(), bad[bad.size() - 3]);
  check.feed("SCIP2.0\n0\n\n", 11);  // SCIP 1.1's status line has no sum
  EXPECT_EQ(check.badLines(), 1u);
}
