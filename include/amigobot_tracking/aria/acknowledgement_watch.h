// Whether the robot still hears the driver. SIPs prove only the robot -> driver direction;
// a request the firmware answers (ENCODER 1 -> one encoder packet) proves the other. If the
// driver -> robot direction dies, the firmware's watchdog stops the robot after 2 s but the
// SIPs keep coming, so without this nothing on the driver's side would notice.
//
// The rule, on the host's clock: a probe is unanswered when a SIP has arrived more than
// `timeout` after the probe was sent and no answer came in between. The answer travels on
// the same byte stream ahead of that SIP, so a late reader (a starved process, a full
// socket buffer) never raises it: only a robot that had the time and did not answer.
// Pure logic, no I/O: the client calls it from its I/O thread.
#pragma once

#include <optional>

namespace amigobot_tracking {
namespace aria {

enum class AcknowledgementState {
  kOff,           // no probing (timeout 0)
  kUntested,      // connected, no answer yet (the first is awaited for `support_wait`)
  kAcknowledged,  // the robot answers
  kUnacknowledged,  // a SIP came > timeout after an unanswered probe: driver -> robot is lost
  kUnsupported,   // no answer at all within `support_wait` of connecting: the firmware does
                  // not answer the probe; probing stops for this connection
};
const char* acknowledgementStateName(AcknowledgementState state);

class AcknowledgementWatch {
 public:
  // period [s] between probes, timeout [s] (0 = off), support_wait [s] for the first answer.
  AcknowledgementWatch(double period, double timeout, double support_wait);

  void connected(double now);  // a new connection: forget everything, probe soon
  bool probeDue(double now) const;
  void probeSent(double now);
  void answered(double now);
  void sipArrived(double now);
  AcknowledgementState state(double now) const;
  // [s] since the oldest unanswered probe was sent (0 when none is unanswered).
  double unansweredFor(double now) const;

 private:
  double period_, timeout_, support_wait_;
  double connected_at_ = 0.0, last_probe_ = -1e300, last_sip_ = -1e300;
  std::optional<double> oldest_unanswered_;
  bool ever_answered_ = false;
};

}  // namespace aria
}  // namespace amigobot_tracking
