#include "amigobot_tracking/core/support/error_text.h"

#include <cctype>
#include <sstream>

namespace amigobot_tracking {
namespace core {
namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// A line of MRPT's block that is not the message: the banner, where it was thrown, the
// backtrace heading and its frames ("[12]  0x55…" or "[3 ] (unknown file) __libc_start_main").
bool isFrameOrHeader(const std::string& line) {
  return startsWith(line, "====") || startsWith(line, "Location:") || startsWith(line, "Call stack backtrace") ||
         (startsWith(line, "[") && line.size() > 1 && std::isdigit(static_cast<unsigned char>(line[1])));
}

std::string printable(const std::string& s, std::size_t max_chars) {
  std::string out;
  for (const char c : s) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (out.size() > max_chars) out = out.substr(0, max_chars > 3 ? max_chars - 3 : 0) + "...";
  return out;
}

}  // namespace

std::string libraryMessage(const std::string& what, std::size_t max_chars) {
  std::istringstream in(what);
  std::string fallback;
  for (std::string line; std::getline(in, line);) {
    line = trimmed(line);
    if (startsWith(line, "Message:")) {
      const std::string message = trimmed(line.substr(8));
      if (!message.empty()) return printable(message, max_chars);
    } else if (fallback.empty() && !line.empty() && !isFrameOrHeader(line)) {
      fallback = line;
    }
  }
  return fallback.empty() ? "unknown error" : printable(fallback, max_chars);
}

}  // namespace core
}  // namespace amigobot_tracking
