// SIP, SYNC2 and CONFIGpac decoding: fixed part, sonar readings, every optional tail
// length, wrong types and short packets.
#include <gtest/gtest.h>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/sip.h"

using namespace amigobot_tracking::aria;

namespace {
Packet parseOne(const std::vector<std::uint8_t>& bytes) {
  PacketParser parser;
  parser.feed(bytes);
  Packet p;
  EXPECT_TRUE(parser.next(p)) << hexDump(bytes);
  return p;
}

Sip sampleSip() {
  Sip s;
  s.type = kSipMoving;
  s.x = 0x7FF0;
  s.y = 12;
  s.theta = -568;
  s.left_vel = -100;
  s.right_vel = 250;
  s.battery = 123;
  s.stall_bumpers = 0x0101;
  s.control = 77;
  s.flags = kFlagMotorsEnabled | 0x2;
  s.compass = 45;
  s.sonars = {{0, 5000}, {3, 1234}, {7, 0}};
  s.grip_state = 1;
  s.anport = 2;
  s.analog = 3;
  s.digin = 4;
  s.digout = 5;
  s.battery_x10 = 129;
  s.charge_state = 1;
  s.rot_vel = -123;
  s.fault_flags = 0x8001;
  s.lat_vel = -7;
  s.temperature = -127;
  s.state_of_charge = 88;
  s.uc_time = 0xDEADBEEF;
  s.flags3 = 0x01020304;
  return s;
}
}  // namespace

TEST(AriaSip, FixedPartAndSonarsRoundTrip) {
  const Sip in = sampleSip();
  const auto out = decodeSip(parseOne(encodeSip(in, 0)));
  ASSERT_TRUE(out);
  EXPECT_EQ(out->type, kSipMoving);
  EXPECT_EQ(out->x, 0x7FF0);
  EXPECT_EQ(out->y, 12);
  EXPECT_EQ(out->theta, -568);
  EXPECT_EQ(out->left_vel, -100);
  EXPECT_EQ(out->right_vel, 250);
  EXPECT_EQ(out->battery, 123);
  EXPECT_TRUE(out->leftStall());
  EXPECT_TRUE(out->rightStall());
  EXPECT_EQ(out->control, 77);
  EXPECT_TRUE(out->motorsEnabled());
  EXPECT_EQ(out->compass, 45);
  ASSERT_EQ(out->sonars.size(), 3u);
  EXPECT_EQ(out->sonars[1].index, 3);
  EXPECT_EQ(out->sonars[1].range, 1234);
  EXPECT_FALSE(out->grip_state);
}

TEST(AriaSip, PositionIsMaskedTo15Bits) {
  std::vector<std::uint8_t> payload(20, 0);
  payload[0] = 0xFF;
  payload[1] = 0xFF;  // XPOS 0xFFFF
  payload[3] = 0x80;  // YPOS 0x8000
  const auto sip = decodeSip(parseOne(encodePacket(kSipStopped, payload)));
  ASSERT_TRUE(sip);
  EXPECT_EQ(sip->x, 0x7FFF);
  EXPECT_EQ(sip->y, 0);
}

TEST(AriaSip, EveryOptionalTailLengthDecodesExactlyThatManyFields) {
  const Sip in = sampleSip();
  for (int n = 0; n <= kSipTailFieldCount; ++n) {
    const auto out = decodeSip(parseOne(encodeSip(in, n)));
    ASSERT_TRUE(out) << "tail " << n;
    const bool present[kSipTailFieldCount] = {
        out->grip_state.has_value(),  out->anport.has_value(),      out->analog.has_value(),
        out->digin.has_value(),       out->digout.has_value(),      out->battery_x10.has_value(),
        out->charge_state.has_value(), out->rot_vel.has_value(),    out->fault_flags.has_value(),
        out->lat_vel.has_value(),     out->temperature.has_value(), out->state_of_charge.has_value(),
        out->uc_time.has_value(),     out->flags3.has_value()};
    for (int i = 0; i < kSipTailFieldCount; ++i) EXPECT_EQ(present[i], i < n) << "tail " << n << " field " << i;
  }
  const auto full = decodeSip(parseOne(encodeSip(in, kSipTailFieldCount)));
  ASSERT_TRUE(full);
  EXPECT_EQ(*full->digout, 5);
  EXPECT_EQ(*full->battery_x10, 129);
  EXPECT_EQ(*full->rot_vel, -123);
  EXPECT_EQ(*full->fault_flags, 0x8001);
  EXPECT_EQ(*full->lat_vel, -7);
  EXPECT_EQ(*full->temperature, -127);
  EXPECT_EQ(*full->state_of_charge, 88);
  EXPECT_EQ(*full->uc_time, 0xDEADBEEFu);
  EXPECT_EQ(*full->flags3, 0x01020304u);
}

TEST(AriaSip, AHalfFieldAtTheEndIsIgnored) {
  std::vector<std::uint8_t> bytes = encodeSip(sampleSip(), 5);
  Packet p = parseOne(bytes);
  p.payload.push_back(0x42);  // one byte of the two-byte BATTERYX10
  const auto out = decodeSip(p);
  ASSERT_TRUE(out);
  EXPECT_TRUE(out->digout);
  EXPECT_FALSE(out->battery_x10);
}

TEST(AriaSip, ShortOrWrongPacketsAreRejectedWithAReason) {
  std::string error;
  Packet p;
  p.type = kSipStopped;
  p.payload.assign(10, 0);
  EXPECT_FALSE(decodeSip(p, &error));
  EXPECT_NE(error.find("fixed part"), std::string::npos) << error;
  p.payload.assign(19, 0);
  p.payload[18] = 4;  // four sonar readings announced, none sent
  EXPECT_FALSE(decodeSip(p, &error));
  EXPECT_NE(error.find("sonar"), std::string::npos) << error;
  p.type = 0x30;
  EXPECT_FALSE(decodeSip(p, &error));
  EXPECT_NE(error.find("type"), std::string::npos) << error;
}

TEST(AriaSync2, IdentityRoundTripsAndSubclassIsLowerCased) {
  const auto id = decodeSync2(parseOne(encodeSync2({"Amigo1", "Pioneer", "AMIGO-SH"})));
  ASSERT_TRUE(id);
  EXPECT_EQ(id->name, "Amigo1");
  EXPECT_EQ(id->robot_class, "Pioneer");
  EXPECT_EQ(id->subclass, "amigo-sh");
  std::string error;
  Packet p;
  p.type = kSync2;
  p.payload = {'A', 0, 'P'};  // subclass missing, class unterminated
  EXPECT_FALSE(decodeSync2(p, &error));
  EXPECT_NE(error.find("SYNC2"), std::string::npos);
}

TEST(AriaConfigPac, RoundTripsAndKeepsTheLimits) {
  ConfigPac c;
  c.robot_type = "Pioneer";
  c.subtype = "amigo";
  c.serial = "AMG123";
  c.rot_vel_top = 300;
  c.trans_vel_top = 1000;
  c.name = "Amigo";
  c.sip_cycle_ms = 100;
  c.watchdog = 2000;
  c.rot_vel_max = 100;
  c.trans_vel_max = 500;
  c.rot_acc = 100;
  c.rot_decel = 120;
  c.trans_acc = 300;
  c.trans_decel = 750;
  c.auto_baud = 2;
  c.drift_factor = -5;
  c.ticks_mm = 38;
  c.firmware_version = "AmigoSH 1.0";
  const auto out = decodeConfigPac(parseOne(encodeConfigPac(c)));
  ASSERT_TRUE(out);
  EXPECT_EQ(out->subtype, "amigo");
  EXPECT_EQ(out->name, "Amigo");
  EXPECT_EQ(out->sip_cycle_ms, 100);
  EXPECT_EQ(out->watchdog, 2000);
  EXPECT_EQ(out->trans_vel_max, 500);
  EXPECT_EQ(out->rot_decel, 120);
  EXPECT_EQ(out->trans_decel, 750);
  EXPECT_EQ(out->auto_baud, 2);
  EXPECT_EQ(out->drift_factor, -5);
  EXPECT_EQ(out->ticks_mm, 38);
  EXPECT_EQ(out->firmware_version, std::string("AmigoSH 1.0"));
}

TEST(AriaConfigPac, OlderShortConfigPacStillDecodesWithoutTheTail) {
  ConfigPac c;
  c.subtype = "amigo";
  Packet p = parseOne(encodeConfigPac(c));
  // Cut everything after TransKI: 14 bytes of optional fields and the empty version string.
  p.payload.resize(p.payload.size() - 15);
  const auto out = decodeConfigPac(p);
  ASSERT_TRUE(out);
  EXPECT_FALSE(out->front_bumps);
  EXPECT_FALSE(out->firmware_version);
  p.payload.resize(p.payload.size() - 1);  // now TransKI is cut
  std::string error;
  EXPECT_FALSE(decodeConfigPac(p, &error));
  EXPECT_NE(error.find("TransKI"), std::string::npos) << error;
}
