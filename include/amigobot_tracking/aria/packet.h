// ARIA packet framing (both directions): FA FB, count, type/command, payload, checksum
// (big-endian). The builder writes typed command arguments; the streaming parser hunts
// for the header, resynchronises after any error and counts each kind of error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace amigobot_tracking {
namespace aria {

constexpr std::uint8_t kHeader0 = 0xFA;
constexpr std::uint8_t kHeader1 = 0xFB;
// Largest count byte we accept or build: type + payload + checksum. The spec says 200
// bytes per packet; ARIA accepts counts up to 255, so the parser's limit is configurable.
constexpr std::size_t kMaxSpecCount = 200;
constexpr std::size_t kMinCount = 3;  // type byte + 2 checksum bytes

// Argument type bytes of client commands.
constexpr std::uint8_t kArgPositive = 0x3B;
constexpr std::uint8_t kArgNegative = 0x1B;
constexpr std::uint8_t kArgString = 0x2B;

// One decoded packet: the byte at offset 3 (command or packet type) and what follows it up
// to the checksum. Offsets in the facts sheet are into the whole packet: payload[i] is
// packet byte i + 4.
struct Packet {
  std::uint8_t type = 0;
  std::vector<std::uint8_t> payload;
};

// ArRobotPacket checksum over `body` (from the type byte up to the checksum): big-endian
// 16-bit words summed mod 2^16, a trailing odd byte XORed in.
std::uint16_t checksum(const std::uint8_t* body, std::size_t size);

// Frames type + payload into a complete packet. Throws std::invalid_argument if it would
// exceed kMaxSpecCount.
std::vector<std::uint8_t> encodePacket(std::uint8_t type, const std::vector<std::uint8_t>& payload);

// Builds the payload of a command argument.
class ArgumentWriter {
 public:
  // 0x3B + uint16 LE, or 0x1B + uint16 LE of |value|. |value| must be <= 65535.
  ArgumentWriter& typedInt(int value);
  // 0x2B, length byte, characters; `nul_terminate` adds ARIA comStr's uncounted NUL.
  ArgumentWriter& typedString(const std::string& text, bool nul_terminate = true);
  // Raw little-endian fields (SIPs and other robot-side packets, SIM_SET_POSE).
  ArgumentWriter& u8(std::uint8_t value);
  ArgumentWriter& u16(std::uint16_t value);
  ArgumentWriter& s16(std::int16_t value) { return u16(static_cast<std::uint16_t>(value)); }
  ArgumentWriter& u32(std::uint32_t value);
  ArgumentWriter& s32(std::int32_t value) { return u32(static_cast<std::uint32_t>(value)); }
  ArgumentWriter& cstring(const std::string& text);  // characters then NUL
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

// Reads little-endian fields from a payload; every read checks the remaining length, so a
// short packet makes ok() false instead of reading past the end.
class PayloadReader {
 public:
  explicit PayloadReader(const std::vector<std::uint8_t>& payload) : data_(payload) {}
  std::uint8_t u8();
  std::int8_t s8() { return static_cast<std::int8_t>(u8()); }
  std::uint16_t u16();
  std::int16_t s16() { return static_cast<std::int16_t>(u16()); }
  std::uint32_t u32();
  std::string cstring();  // up to NUL (or end of payload, which is an error)
  std::size_t remaining() const { return ok_ ? data_.size() - pos_ : 0; }
  bool ok() const { return ok_; }

 private:
  bool need(std::size_t n);
  const std::vector<std::uint8_t>& data_;
  std::size_t pos_ = 0;
  bool ok_ = true;
};

struct ParserStats {
  std::uint64_t packets = 0;          // good packets delivered
  std::uint64_t garbage_bytes = 0;    // bytes skipped while hunting for FA FB
  std::uint64_t bad_count = 0;        // count byte below 3 or above the limit
  std::uint64_t bad_checksum = 0;     // full packet whose checksum did not match
  std::uint64_t truncated = 0;        // packet cut short by a new header or a timeout
  std::uint64_t errors() const { return bad_count + bad_checksum + truncated; }
};

// Streaming parser: feed any split of bytes, take complete packets out. After an error it
// resumes the header hunt at the byte after the failed header, so a good packet hidden
// inside a corrupted one is still found.
class PacketParser {
 public:
  explicit PacketParser(std::size_t max_count = kMaxSpecCount) : max_count_(max_count) {}

  // Appends bytes; complete packets are queued for next().
  void feed(const std::uint8_t* data, std::size_t size);
  void feed(const std::vector<std::uint8_t>& data) { feed(data.data(), data.size()); }
  // Takes the oldest complete packet; false when none is ready.
  bool next(Packet& out);
  // Abandons a partial packet (the link was silent for too long: ARIA uses 100 ms between
  // bytes). Counts it as truncated if a header had been seen.
  void expirePartial();
  bool hasPartial() const { return !buffer_.empty(); }
  void reset();
  const ParserStats& stats() const { return stats_; }

 private:
  void scan();
  std::size_t max_count_;
  std::vector<std::uint8_t> buffer_;  // unconsumed bytes, starting at a candidate header
  std::vector<Packet> ready_;
  std::size_t ready_head_ = 0;
  ParserStats stats_;
};

// "FA FB 03 00 00 00" style hex dump for logs and error messages.
std::string hexDump(const std::uint8_t* data, std::size_t size);
inline std::string hexDump(const std::vector<std::uint8_t>& d) { return hexDump(d.data(), d.size()); }

}  // namespace aria
}  // namespace amigobot_tracking
