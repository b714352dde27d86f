#include "amigobot_tracking/localization/localization_verdict.h"

#include <cstdio>

namespace amigobot_tracking {
namespace localization {

namespace {

std::string format(const char* pattern, double a, double b) {
  char text[120];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

}  // namespace

void LocalizationVerdict::poseSet() {
  state_ = State::kConverging;
  agreeing_ = 0;
  reason_ = "pose set, no scan agreed with it yet";
}

LocalizationVerdict::State LocalizationVerdict::update(const ScanEvidence& scan) {
  if (!(scan.match >= config_.min_match)) {  // NaN is lost too
    state_ = State::kLost;
    agreeing_ = 0;
    reason_ = format("match %.2f < min_match %.2f", scan.match, config_.min_match);
    return state_;
  }
  if (scan.correction > config_.max_correction || scan.correction_angle > config_.max_correction_angle) {
    state_ = State::kConverging;
    agreeing_ = 0;
    reason_ = format("scan match moved the pose %.2f m (bound %.2f m)", scan.correction, config_.max_correction);
    return state_;
  }
  if (state_ == State::kLocalized) return state_;
  if (scan.match >= config_.localized_match) {
    ++agreeing_;
  } else {
    agreeing_ = 0;
  }
  if (agreeing_ >= config_.window) {
    state_ = State::kLocalized;
    reason_.clear();
  } else {
    state_ = State::kConverging;
    reason_ = format("converging: match %.2f, %.0f scans", scan.match, static_cast<double>(agreeing_)) +
              " in a row >= localized_match " + format("%.2f of %.0f", config_.localized_match, config_.window);
  }
  return state_;
}

}  // namespace localization
}  // namespace amigobot_tracking
