// Hokuyo SCIP 2.0, the sensor side: the character encoding, the checksum and the replies a
// URG sends (Hokuyo's "Communication Protocol Specification for SCIP2.0"). Pure functions,
// no I/O: the laser emulator frames its replies with them and the tests check them against
// the specification's own examples.
//
// A reply is the echo of the command line, a status line "SS" + sum, then data lines each
// followed by its sum character, and an empty line. Each data line of a scan carries at most
// 64 characters.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace amigobot_tracking {
namespace sensors {
namespace scip {

// The sum character of `text`: the low 6 bits of the byte sum, plus 0x30.
char checksum(const std::string& text);
// Encodes `value` in `chars` characters of 6 bits each (+0x30), most significant first.
// Throws std::out_of_range when it does not fit.
std::string encode(std::uint32_t value, int chars);
// Decodes characters written by encode(); throws std::invalid_argument on a character
// outside 0x30..0x6F.
std::uint32_t decode(const std::string& chars);

// The status line with its sum, e.g. "00P".
std::string statusLine(const std::string& status);
// A reply without data lines: echo, status, empty line.
std::string reply(const std::string& command, const std::string& status);
// A reply of "LABEL:value" lines (VV, PP, II): each line is "LABEL:value;" + the sum of
// "LABEL:value".
std::string infoReply(const std::string& command, const std::vector<std::string>& entries);
// One MD/GD data reply: the 4-character time stamp [ms] then the ranges [mm] in `chars`
// characters each (3 for MD/GD, 2 for MS/GS), cut into lines of 64 characters.
std::string scanReply(const std::string& echo, const std::string& status, std::uint32_t stamp_ms,
                      const std::vector<std::uint32_t>& ranges_mm, int chars);

// A parsed MD/MS/GD/GS request: "MD" start(4) end(4) cluster(2) [interval(1) count(2)].
struct ScanRequest {
  std::string command;  // MD, MS, GD or GS
  int start = 0, end = 0, cluster = 1, interval = 0, count = 0;
  bool continuous() const { return command[0] == 'M'; }
  int encodingChars() const { return command[1] == 'D' ? 3 : 2; }
};
// Empty when `line` (without its line feed) is a well-formed scan request, else what is wrong.
std::string parseScanRequest(const std::string& line, ScanRequest* request);

// Checks the sums of the replies in a byte stream as it is read: in each reply (lines up to
// an empty line) every line after the echo whose length is at least 2 ends with the sum of
// the rest (status and data lines; SCIP 1.1's one-character status has none), an info line
// "LABEL:value;" with the sum of "LABEL:value".
class ReplySumCheck {
 public:
  void feed(const char* bytes, std::size_t count);
  std::uint64_t badLines() const { return bad_; }
  const std::string& lastBad() const { return last_bad_; }  // the last line with a wrong sum

 private:
  std::string line_, last_bad_;
  bool echo_next_ = true;  // the next line is a command echo
  std::uint64_t bad_ = 0;
};

}  // namespace scip
}  // namespace sensors
}  // namespace amigobot_tracking
