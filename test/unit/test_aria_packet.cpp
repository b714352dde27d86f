// Packet framing, checksum, command builders (byte vectors from the facts sheet) and the
// streaming parser under garbage, split reads, wrong counts and checksums.
#include <gtest/gtest.h>

#include <random>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/packet.h"

using namespace amigobot_tracking::aria;
using Bytes = std::vector<std::uint8_t>;

TEST(AriaPacket, SyncPacketsMatchTheFactsSheet) {
  EXPECT_EQ(syncPacket(0), (Bytes{0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00}));
  EXPECT_EQ(syncPacket(1), (Bytes{0xFA, 0xFB, 0x03, 0x01, 0x00, 0x01}));
  EXPECT_EQ(syncPacket(2), (Bytes{0xFA, 0xFB, 0x03, 0x02, 0x00, 0x02}));
  EXPECT_EQ(commandPacket(Command::kClose), (Bytes{0xFA, 0xFB, 0x03, 0x02, 0x00, 0x02}));
  EXPECT_THROW(syncPacket(3), std::invalid_argument);
}

TEST(AriaPacket, IntCommandsMatchTheFactsSheet) {
  EXPECT_EQ(commandPacket(Command::kVel, 200), (Bytes{0xFA, 0xFB, 0x06, 0x0B, 0x3B, 0xC8, 0x00, 0xD3, 0x3B}));
  EXPECT_EQ(commandPacket(Command::kVel, -200), (Bytes{0xFA, 0xFB, 0x06, 0x0B, 0x1B, 0xC8, 0x00, 0xD3, 0x1B}));
  EXPECT_EQ(commandPacket(Command::kEnable, 1), (Bytes{0xFA, 0xFB, 0x06, 0x04, 0x3B, 0x01, 0x00, 0x05, 0x3B}));
  EXPECT_EQ(commandPacket(Command::kOpen, 1), (Bytes{0xFA, 0xFB, 0x06, 0x01, 0x3B, 0x01, 0x00, 0x02, 0x3B}));
  EXPECT_THROW(commandPacket(Command::kVel, 70000), std::invalid_argument);
}

TEST(AriaPacket, Vel2PacksLeftHighRightLowAsSigned16) {
  EXPECT_EQ(vel2Packet(-10, 5), (Bytes{0xFA, 0xFB, 0x06, 0x20, 0x1B, 0xFB, 0x09, 0x1B, 0x24}));
  // Every pair survives the round trip through the signed 16-bit value the robot rebuilds,
  // including a negative right wheel (ARIA's (l<<8)+r would borrow from the left byte).
  for (int l = -128; l <= 127; l += 5) {
    for (int r = -128; r <= 127; r += 3) {
      int l2 = 0, r2 = 0;
      unpackVel2(packVel2(l, r), l2, r2);
      ASSERT_EQ(l2, l);
      ASSERT_EQ(r2, r);
    }
  }
}

TEST(AriaPacket, Vel2ClampsTo127InsteadOfWrappingToMinus128) {
  int l = 0, r = 0;
  unpackVel2(packVel2(128, 300), l, r);
  EXPECT_EQ(l, 127);
  EXPECT_EQ(r, 127);
  unpackVel2(packVel2(-129, -1000), l, r);
  EXPECT_EQ(l, -128);
  EXPECT_EQ(r, -128);
}

TEST(AriaPacket, ArgumentsDecodeOnTheRobotSide) {
  Packet p;
  PacketParser parser;
  parser.feed(commandPacket(Command::kRVel, -45));
  ASSERT_TRUE(parser.next(p));
  EXPECT_EQ(p.type, static_cast<std::uint8_t>(Command::kRVel));
  EXPECT_EQ(intArgument(p), -45);
  parser.feed(commandPacket(Command::kPolling, std::string("abc")));
  ASSERT_TRUE(parser.next(p));
  EXPECT_EQ(stringArgument(p), std::string("abc"));
  EXPECT_FALSE(intArgument(p).has_value());
  parser.feed(commandPacket(Command::kPulse));
  ASSERT_TRUE(parser.next(p));
  EXPECT_FALSE(intArgument(p).has_value());
}

TEST(AriaPacket, ChecksumXorsTheOddByte) {
  const std::uint8_t odd[] = {0x12, 0x34, 0x56};
  EXPECT_EQ(checksum(odd, 3), 0x1234 ^ 0x56);
  const std::uint8_t wrap[] = {0xFF, 0xFF, 0x00, 0x02};
  EXPECT_EQ(checksum(wrap, 4), 0x0001);
}

TEST(AriaPacket, BuilderRefusesOversizedPackets) {
  EXPECT_NO_THROW(encodePacket(0x20, Bytes(197, 0)));
  EXPECT_THROW(encodePacket(0x20, Bytes(198, 0)), std::invalid_argument);
}

namespace {
Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

std::vector<Packet> parseAll(PacketParser& parser, const Bytes& stream, std::size_t chunk) {
  std::vector<Packet> out;
  for (std::size_t i = 0; i < stream.size(); i += chunk) {
    parser.feed(stream.data() + i, std::min(chunk, stream.size() - i));
    Packet p;
    while (parser.next(p)) out.push_back(p);
  }
  return out;
}
}  // namespace

TEST(AriaParser, OneByteAtATimeGivesTheSamePackets) {
  const Bytes stream = concat({syncPacket(0), commandPacket(Command::kVel, 200), vel2Packet(-10, 5)});
  for (std::size_t chunk : {std::size_t{1}, std::size_t{2}, std::size_t{5}, stream.size()}) {
    PacketParser parser;
    const auto packets = parseAll(parser, stream, chunk);
    ASSERT_EQ(packets.size(), 3u) << "chunk " << chunk;
    EXPECT_EQ(packets[1].type, 0x0B);
    EXPECT_EQ(intArgument(packets[1]), 200);
    EXPECT_EQ(parser.stats().errors(), 0u);
    EXPECT_EQ(parser.stats().garbage_bytes, 0u);
  }
}

TEST(AriaParser, SkipsAndCountsGarbage) {
  const Bytes garbage{0x00, 0x11, 0xFA, 0x22, 0xFB, 0x33};
  const Bytes stream = concat({garbage, syncPacket(1), Bytes{0x44}});
  PacketParser parser;
  const auto packets = parseAll(parser, stream, 1);
  ASSERT_EQ(packets.size(), 1u);
  EXPECT_EQ(packets[0].type, 1);
  EXPECT_EQ(parser.stats().garbage_bytes, garbage.size() + 1);
  EXPECT_EQ(parser.stats().errors(), 0u);
}

TEST(AriaParser, BadChecksumIsDroppedAndCounted) {
  Bytes bad = commandPacket(Command::kVel, 200);
  bad.back() ^= 0x01;
  PacketParser parser;
  const auto packets = parseAll(parser, concat({bad, syncPacket(2)}), 3);
  ASSERT_EQ(packets.size(), 1u);
  EXPECT_EQ(packets[0].type, 2);
  EXPECT_EQ(parser.stats().bad_checksum, 1u);
  EXPECT_EQ(parser.stats().truncated, 0u);
}

TEST(AriaParser, WrongCountsAreCountedAndResynchronised) {
  PacketParser parser;
  const Bytes too_small{0xFA, 0xFB, 0x02, 0x00};
  const Bytes too_big{0xFA, 0xFB, 0xF0};
  const auto packets = parseAll(parser, concat({too_small, too_big, syncPacket(0)}), 1);
  ASSERT_EQ(packets.size(), 1u);
  EXPECT_EQ(parser.stats().bad_count, 2u);
  // A larger limit (ARIA accepts up to 255) admits the count instead.
  PacketParser lenient(255);
  lenient.feed(Bytes{0xFA, 0xFB, 0xF0});
  EXPECT_EQ(lenient.stats().bad_count, 0u);
  EXPECT_TRUE(lenient.hasPartial());
}

TEST(AriaParser, TruncatedPacketFollowedByAGoodOneIsRecovered) {
  const Bytes full = commandPacket(Command::kVel, 200);
  const Bytes cut(full.begin(), full.begin() + 5);  // header, count, type, arg type
  PacketParser parser;
  const auto packets = parseAll(parser, concat({cut, syncPacket(2), syncPacket(1)}), 1);
  ASSERT_EQ(packets.size(), 2u);
  EXPECT_EQ(packets[0].type, 2);
  EXPECT_EQ(packets[1].type, 1);
  EXPECT_EQ(parser.stats().truncated, 1u);
  EXPECT_EQ(parser.stats().bad_checksum, 0u);
}

TEST(AriaParser, SilenceExpiresAPartialPacket) {
  const Bytes full = commandPacket(Command::kVel, 200);
  PacketParser parser;
  parser.feed(full.data(), 5);
  EXPECT_TRUE(parser.hasPartial());
  parser.expirePartial();
  EXPECT_FALSE(parser.hasPartial());
  EXPECT_EQ(parser.stats().truncated, 1u);
  parser.feed(syncPacket(0));
  Packet p;
  EXPECT_TRUE(parser.next(p));
}

TEST(AriaParser, RandomNoiseBetweenPacketsNeverLosesAGoodPacket) {
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> byte(0, 255);
  Bytes stream;
  const int kPackets = 200;
  for (int i = 0; i < kPackets; ++i) {
    // Noise without FA, so it cannot start a false header that swallows the next packet.
    for (int n = byte(rng) % 8; n > 0; --n) {
      int b = byte(rng);
      stream.push_back(static_cast<std::uint8_t>(b == 0xFA ? 0 : b));
    }
    const Bytes p = commandPacket(Command::kVel, i);
    stream.insert(stream.end(), p.begin(), p.end());
  }
  PacketParser parser;
  const auto packets = parseAll(parser, stream, 7);
  ASSERT_EQ(packets.size(), static_cast<std::size_t>(kPackets));
  for (int i = 0; i < kPackets; ++i) EXPECT_EQ(intArgument(packets[i]), i);
}

TEST(AriaParser, HexDumpIsReadable) { EXPECT_EQ(hexDump(syncPacket(1)), "FA FB 03 01 00 01"); }
