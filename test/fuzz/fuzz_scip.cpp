// libFuzzer target: the SCIP (Hokuyo URG) parsers on arbitrary bytes: the reply sum check
// as the driver's stream feeds it (split at arbitrary points), the scan-request parser of
// the emulator, and the range decoder. Invariants: no crash or UB; a request that parses
// has its fields in range; the split feed counts the same bad lines as one feed.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/sensors/scip.h"
#include "fuzz_support.h"

using namespace amigobot_tracking::sensors;
using fuzz_support::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t chunk = 1 + data[0] % 32;
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  scip::ReplySumCheck whole, split;
  whole.feed(bytes.data(), bytes.size());
  for (std::size_t i = 0; i < bytes.size(); i += chunk) split.feed(bytes.data() + i, std::min(chunk, bytes.size() - i));
  check(whole.badLines() == split.badLines());
  std::size_t start = 0;
  for (std::size_t end; (end = bytes.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = bytes.substr(start, end - start);
    scip::ScanRequest request;
    if (scip::parseScanRequest(line, &request).empty()) {
      check(request.command.size() == 2);
      check(request.encodingChars() == 2 || request.encodingChars() == 3);
    }
    try {
      if (line.size() <= 4) scip::decode(line);
    } catch (const std::invalid_argument&) {  // its contract for a character outside 0x30..0x6F
    }
  }
  return 0;
}
