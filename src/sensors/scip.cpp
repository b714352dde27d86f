#include "amigobot_tracking/sensors/scip.h"

#include <cctype>
#include <stdexcept>

namespace amigobot_tracking {
namespace sensors {
namespace scip {
namespace {

constexpr std::size_t kLineChars = 64;

bool digits(const std::string& text, std::size_t from, std::size_t count, int* value) {
  if (from + count > text.size()) return false;
  *value = 0;
  for (std::size_t i = from; i < from + count; ++i) {
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) return false;
    *value = *value * 10 + (text[i] - '0');
  }
  return true;
}

}  // namespace

char checksum(const std::string& text) {
  unsigned sum = 0;
  for (unsigned char c : text) sum += c;
  return static_cast<char>((sum & 0x3F) + 0x30);
}

std::string encode(std::uint32_t value, int chars) {
  if (chars < 1 || chars > 5 || (chars < 5 && value >> (6 * chars) != 0)) {
    throw std::out_of_range("scip::encode: " + std::to_string(value) + " does not fit in " +
                            std::to_string(chars) + " characters");
  }
  std::string out(static_cast<std::size_t>(chars), '0');
  for (int i = chars - 1; i >= 0; --i, value >>= 6) out[static_cast<std::size_t>(i)] = static_cast<char>((value & 0x3F) + 0x30);
  return out;
}

std::uint32_t decode(const std::string& chars) {
  std::uint32_t value = 0;
  for (unsigned char c : chars) {
    if (c < 0x30 || c > 0x6F) throw std::invalid_argument("scip::decode: character " + std::to_string(c) + " out of range");
    value = (value << 6) | (c - 0x30u);
  }
  return value;
}

std::string statusLine(const std::string& status) { return status + checksum(status); }

std::string reply(const std::string& command, const std::string& status) {
  return command + "\n" + statusLine(status) + "\n\n";
}

std::string infoReply(const std::string& command, const std::vector<std::string>& entries) {
  std::string out = command + "\n" + statusLine("00") + "\n";
  for (const std::string& entry : entries) out += entry + ";" + checksum(entry) + "\n";
  return out + "\n";
}

std::string scanReply(const std::string& echo, const std::string& status, std::uint32_t stamp_ms,
                      const std::vector<std::uint32_t>& ranges_mm, int chars) {
  const std::string stamp = encode(stamp_ms & 0xFFFFFFu, 4);
  std::string out = echo + "\n" + statusLine(status) + "\n" + stamp + checksum(stamp) + "\n";
  std::string data;
  for (std::uint32_t range : ranges_mm) data += encode(range, chars);
  for (std::size_t at = 0; at < data.size(); at += kLineChars) {
    const std::string line = data.substr(at, kLineChars);
    out += line + checksum(line) + "\n";
  }
  return out + "\n";
}

std::string parseScanRequest(const std::string& line, ScanRequest* request) {
  ScanRequest r;
  r.command = line.substr(0, 2);
  if (r.command != "MD" && r.command != "MS" && r.command != "GD" && r.command != "GS") {
    return "not a scan request: '" + line + "'";
  }
  const std::size_t length = r.continuous() ? 15 : 12;
  if (line.size() != length) {
    return r.command + ": expected " + std::to_string(length) + " characters, got " + std::to_string(line.size());
  }
  if (!digits(line, 2, 4, &r.start) || !digits(line, 6, 4, &r.end) || !digits(line, 10, 2, &r.cluster) ||
      (r.continuous() && (!digits(line, 12, 1, &r.interval) || !digits(line, 13, 2, &r.count)))) {
    return r.command + ": non-digit parameter in '" + line + "'";
  }
  if (r.start > r.end) return r.command + ": start step " + std::to_string(r.start) + " after end step " + std::to_string(r.end);
  if (r.cluster == 0) r.cluster = 1;  // "00" and "01" both mean no grouping
  *request = r;
  return "";
}

void ReplySumCheck::feed(const char* bytes, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    if (bytes[i] != '\n') {
      line_ += bytes[i];
      continue;
    }
    if (line_.empty()) {
      echo_next_ = true;  // end of a reply
    } else if (echo_next_) {
      echo_next_ = false;
    } else if (line_.size() >= 2 && line_.back() != checksum(line_.substr(0, line_.size() - 1)) &&
               !(line_.size() >= 3 && line_[line_.size() - 2] == ';' &&
                 line_.back() == checksum(line_.substr(0, line_.size() - 2)))) {
      ++bad_;  // (an info line "LABEL:value;" + sum is summed without its ';')
      last_bad_ = line_;
    }
    line_.clear();
  }
}

}  // namespace scip
}  // namespace sensors
}  // namespace amigobot_tracking
