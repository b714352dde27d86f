// Whether the localisation is good enough to drive on (issue 25: after a wrong /initialpose the
// node said "localized" again while 1.07 m off, because it only compared the match with
// min_match). "Localized" needs the match and the pose to agree over a window of scans:
// - lost:      the match at the estimated pose is below min_match;
// - not yet:   since the pose was set (start, /initialpose, global localisation) or since the
//              last jump (a scan-matched correction larger than max_correction, the tracking
//              bound), fewer than `window` consecutive scans have matched at least
//              localized_match with corrections within the bound; a wrong pose in a local
//              minimum of ICP fits part of the scan (above min_match) but not localized_match;
// - localized: after such a window; it stays so while the match is >= min_match and no
//              correction jumps (hysteresis: a passer-by in the scan does not stop the robot).
// Pure and ROS-free; one caller.
#pragma once

#include <string>

namespace amigobot_tracking {
namespace localization {

struct VerdictConfig {
  double min_match = 0.4;             // [-] below: lost
  double localized_match = 0.8;       // [-] the match a window of scans must reach to say "localized"
  double max_correction = 0.1;        // [m] a larger scan-matched correction is a jump (the tracking bound)
  double max_correction_angle = 0.1;  // [rad] the same for the heading
  int window = 5;                     // scans in a row that must agree
};

// What one scan says about the pose the engine holds.
struct ScanEvidence {
  double match = 0.0;        // fraction of beams on the map at the estimated pose, [0, 1]
  double correction = 0.0;   // [m] how far this scan's match moved the pose (0: not matched)
  double correction_angle = 0.0;  // [rad] the same for the heading, absolute
};

class LocalizationVerdict {
 public:
  enum class State { kLost, kConverging, kLocalized };

  explicit LocalizationVerdict(const VerdictConfig& config) : config_(config) {}
  // The pose was set from outside (start, /initialpose, global localisation): not localized
  // until the scans agree with it.
  void poseSet();
  State update(const ScanEvidence& scan);
  State state() const { return state_; }
  bool localized() const { return state_ == State::kLocalized; }
  // "" when localized, else why not (for LocalizationStatus.reason and the diagnostics).
  const std::string& reason() const { return reason_; }

 private:
  VerdictConfig config_;
  State state_ = State::kConverging;
  int agreeing_ = 0;  // consecutive scans that agree with the pose
  std::string reason_ = "no scan matched at the pose yet";
};

}  // namespace localization
}  // namespace amigobot_tracking
