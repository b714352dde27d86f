#include "amigobot_tracking/aria/packet.h"

#include <cstdio>
#include <stdexcept>

namespace amigobot_tracking {
namespace aria {

std::uint16_t checksum(const std::uint8_t* body, std::size_t size) {
  std::uint32_t sum = 0;
  std::size_t i = 0;
  for (; i + 1 < size; i += 2) {
    sum = (sum + ((static_cast<std::uint32_t>(body[i]) << 8) | body[i + 1])) & 0xFFFF;
  }
  if (i < size) sum ^= body[i];
  return static_cast<std::uint16_t>(sum);
}

std::vector<std::uint8_t> encodePacket(std::uint8_t type, const std::vector<std::uint8_t>& payload) {
  const std::size_t count = 1 + payload.size() + 2;
  if (count > kMaxSpecCount) {
    throw std::invalid_argument("ARIA packet type " + std::to_string(type) + ": count " + std::to_string(count) +
                                " exceeds the " + std::to_string(kMaxSpecCount) + "-byte limit");
  }
  std::vector<std::uint8_t> out;
  out.reserve(count + 3);
  out.push_back(kHeader0);
  out.push_back(kHeader1);
  out.push_back(static_cast<std::uint8_t>(count));
  out.push_back(type);
  out.insert(out.end(), payload.begin(), payload.end());
  const std::uint16_t sum = checksum(out.data() + 3, out.size() - 3);
  out.push_back(static_cast<std::uint8_t>(sum >> 8));
  out.push_back(static_cast<std::uint8_t>(sum & 0xFF));
  return out;
}

ArgumentWriter& ArgumentWriter::typedInt(int value) {
  const long magnitude = value < 0 ? -static_cast<long>(value) : value;
  if (magnitude > 0xFFFF) {
    throw std::invalid_argument("ARIA int argument " + std::to_string(value) + " does not fit 16 bits");
  }
  bytes_.push_back(value < 0 ? kArgNegative : kArgPositive);
  return u16(static_cast<std::uint16_t>(magnitude));
}

ArgumentWriter& ArgumentWriter::typedString(const std::string& text, bool nul_terminate) {
  if (text.size() > 199) throw std::invalid_argument("ARIA string argument longer than 199 characters");
  bytes_.push_back(kArgString);
  bytes_.push_back(static_cast<std::uint8_t>(text.size()));
  bytes_.insert(bytes_.end(), text.begin(), text.end());
  if (nul_terminate) bytes_.push_back(0);
  return *this;
}

ArgumentWriter& ArgumentWriter::u8(std::uint8_t value) {
  bytes_.push_back(value);
  return *this;
}

ArgumentWriter& ArgumentWriter::u16(std::uint16_t value) {
  bytes_.push_back(static_cast<std::uint8_t>(value & 0xFF));
  bytes_.push_back(static_cast<std::uint8_t>(value >> 8));
  return *this;
}

ArgumentWriter& ArgumentWriter::u32(std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) bytes_.push_back(static_cast<std::uint8_t>((value >> shift) & 0xFF));
  return *this;
}

ArgumentWriter& ArgumentWriter::cstring(const std::string& text) {
  bytes_.insert(bytes_.end(), text.begin(), text.end());
  bytes_.push_back(0);
  return *this;
}

bool PayloadReader::need(std::size_t n) {
  if (!ok_ || data_.size() - pos_ < n) ok_ = false;
  return ok_;
}

std::uint8_t PayloadReader::u8() {
  if (!need(1)) return 0;
  return data_[pos_++];
}

std::uint16_t PayloadReader::u16() {
  if (!need(2)) return 0;
  const std::uint16_t v = static_cast<std::uint16_t>(data_[pos_] | (data_[pos_ + 1] << 8));
  pos_ += 2;
  return v;
}

std::uint32_t PayloadReader::u32() {
  if (!need(4)) return 0;
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | data_[pos_ + i];
  pos_ += 4;
  return v;
}

std::string PayloadReader::cstring() {
  std::string out;
  while (ok_) {
    if (pos_ >= data_.size()) {
      ok_ = false;  // no terminating NUL
      break;
    }
    const char c = static_cast<char>(data_[pos_++]);
    if (c == '\0') break;
    out.push_back(c);
  }
  return out;
}

void PacketParser::feed(const std::uint8_t* data, std::size_t size) {
  buffer_.insert(buffer_.end(), data, data + size);
  scan();
}

void PacketParser::scan() {
  std::size_t start = 0;
  while (start < buffer_.size()) {
    const std::size_t avail = buffer_.size() - start;
    if (buffer_[start] != kHeader0 || (avail >= 2 && buffer_[start + 1] != kHeader1)) {
      ++stats_.garbage_bytes;
      ++start;
      continue;
    }
    if (avail < 3) break;
    const std::size_t count = buffer_[start + 2];
    if (count < kMinCount || count > max_count_) {
      ++stats_.bad_count;
      start += 1;  // resume the hunt just after this false header
      continue;
    }
    if (avail < count + 3) break;
    const std::uint8_t* body = buffer_.data() + start + 3;
    const std::size_t body_size = count - 2;
    const std::uint16_t expected = static_cast<std::uint16_t>((body[body_size] << 8) | body[body_size + 1]);
    if (checksum(body, body_size) != expected) {
      // A header inside the body means this packet was cut short by the next one.
      bool new_header_inside = false;
      for (std::size_t i = 0; i + 1 < count; ++i) {
        if (body[i] == kHeader0 && body[i + 1] == kHeader1) new_header_inside = true;
      }
      ++(new_header_inside ? stats_.truncated : stats_.bad_checksum);
      start += 1;
      continue;
    }
    Packet packet;
    packet.type = body[0];
    packet.payload.assign(body + 1, body + body_size);
    ready_.push_back(std::move(packet));
    ++stats_.packets;
    start += count + 3;
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(start));
}

bool PacketParser::next(Packet& out) {
  if (ready_head_ >= ready_.size()) {
    ready_.clear();
    ready_head_ = 0;
    return false;
  }
  out = std::move(ready_[ready_head_++]);
  return true;
}

void PacketParser::expirePartial() {
  if (buffer_.empty()) return;
  // Only a partial packet (a header was seen) counts as truncated; a lone FA is garbage.
  if (buffer_.size() >= 2) {
    ++stats_.truncated;
  } else {
    ++stats_.garbage_bytes;
  }
  // The bytes after the abandoned header may still hold a complete packet.
  buffer_.erase(buffer_.begin());
  scan();
}

void PacketParser::reset() {
  buffer_.clear();
  ready_.clear();
  ready_head_ = 0;
}

std::string hexDump(const std::uint8_t* data, std::size_t size) {
  std::string out;
  char byte[4];
  for (std::size_t i = 0; i < size; ++i) {
    std::snprintf(byte, sizeof(byte), i ? " %02X" : "%02X", data[i]);
    out += byte;
  }
  return out;
}

}  // namespace aria
}  // namespace amigobot_tracking
