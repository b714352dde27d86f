// libFuzzer target: the emulator's status line parser and its control line parser
// ("teleport x y theta") on arbitrary text. Invariants: no crash or UB; a line that parses is
// finite, and formatting it gives a line that parses back to exactly the same values (%.17g).
#include <cstddef>
#include <cstdint>
#include <string>

#include "amigobot_tracking/aria/emulator_status.h"
#include "fuzz_support.h"

using namespace amigobot_tracking::aria;
using fuzz_support::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string line(reinterpret_cast<const char*>(data), size);
  amigobot_tracking::core::Pose2 pose, pose_again;
  if (parseControlLine(line, &pose).empty()) {
    check(pose.isFinite());
    check(parseControlLine(formatTeleportLine(pose), &pose_again).empty());
    check(pose_again.x == pose.x && pose_again.y == pose.y && pose_again.theta == pose.theta);
  }
  EmulatorStatus status;
  if (!parseStatusLine(line, &status).empty()) return 0;
  check(std::isfinite(status.t) && status.pose.isFinite());
  EmulatorStatus again;
  const std::string written = formatStatusLine(status);
  check(parseStatusLine(written, &again).empty());
  check(again.t == status.t && again.pose.x == status.pose.x && again.pose.y == status.pose.y &&
        again.pose.theta == status.pose.theta && again.v == status.v && again.w == status.w &&
        again.motors == status.motors && again.open == status.open && again.watchdog == status.watchdog);
  return 0;
}
