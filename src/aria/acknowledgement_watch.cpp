#include "amigobot_tracking/aria/acknowledgement_watch.h"

namespace amigobot_tracking {
namespace aria {

const char* acknowledgementStateName(AcknowledgementState state) {
  switch (state) {
    case AcknowledgementState::kOff: return "off";
    case AcknowledgementState::kUntested: return "untested";
    case AcknowledgementState::kAcknowledged: return "acknowledged";
    case AcknowledgementState::kUnacknowledged: return "unacknowledged";
    case AcknowledgementState::kUnsupported: return "unsupported";
  }
  return "unknown";
}

AcknowledgementWatch::AcknowledgementWatch(double period, double timeout, double support_wait)
    : period_(period), timeout_(timeout), support_wait_(support_wait) {}

void AcknowledgementWatch::connected(double now) {
  connected_at_ = now;
  last_probe_ = last_sip_ = -1e300;
  oldest_unanswered_.reset();
  ever_answered_ = false;
}

bool AcknowledgementWatch::probeDue(double now) const {
  const AcknowledgementState s = state(now);
  if (s == AcknowledgementState::kOff || s == AcknowledgementState::kUnsupported) return false;
  return now - last_probe_ >= period_;
}

void AcknowledgementWatch::probeSent(double now) {
  last_probe_ = now;
  if (!oldest_unanswered_) oldest_unanswered_ = now;
}

void AcknowledgementWatch::answered(double /*now*/) {
  // Answers carry no number: one answers every probe sent before it.
  oldest_unanswered_.reset();
  ever_answered_ = true;
}

void AcknowledgementWatch::sipArrived(double now) { last_sip_ = now; }

AcknowledgementState AcknowledgementWatch::state(double now) const {
  if (timeout_ <= 0.0) return AcknowledgementState::kOff;
  if (!ever_answered_) {
    return now - connected_at_ > support_wait_ ? AcknowledgementState::kUnsupported
                                               : AcknowledgementState::kUntested;
  }
  if (oldest_unanswered_ && last_sip_ - *oldest_unanswered_ > timeout_) return AcknowledgementState::kUnacknowledged;
  return AcknowledgementState::kAcknowledged;
}

double AcknowledgementWatch::unansweredFor(double now) const {
  return oldest_unanswered_ ? now - *oldest_unanswered_ : 0.0;
}

}  // namespace aria
}  // namespace amigobot_tracking
