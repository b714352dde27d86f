// libFuzzer target: the CoLa-A (SICK LMS1xx) telegram framing and scan decoder on arbitrary
// bytes split at arbitrary points. Invariants: no crash or UB; every body taken out came
// from the input; a decoded scan re-encodes into a telegram that decodes to the same scan.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "amigobot_tracking/sensors/cola_a.h"
#include "fuzz_support.h"

using namespace amigobot_tracking::sensors;
using fuzz_support::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t chunk = 1 + data[0] % 64;
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::string buffer, body;
  std::size_t taken = 0;
  for (std::size_t i = 0; i < bytes.size(); i += chunk) {
    buffer.append(bytes, i, chunk);
    while (cola::nextTelegram(&buffer, &body)) {
      taken += body.size() + 2;
      check(taken <= bytes.size());
      cola::ScanTelegram scan;
      if (!cola::decodeScan(body, &scan).empty()) continue;
      cola::ScanTelegram again;
      const std::string encoded = cola::encodeScan(scan);
      check(cola::decodeScan(encoded, &again).empty());
      check(again.ranges == scan.ranges && again.start_angle == scan.start_angle &&
            again.angular_step == scan.angular_step && again.command == scan.command);
    }
  }
  return 0;
}
