// The client's check that the robot still hears it (aria/acknowledgement_watch.h): one
// ENCODER request per probe period, its answer, the state and its changes in the log.
#include <cstdio>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/aria/commands.h"

namespace amigobot_tracking {
namespace aria {

void AriaClient::probeAcknowledgement(Clock::time_point now) {
  const double t = std::chrono::duration<double>(now.time_since_epoch()).count();
  const bool probe = ack_watch_.probeDue(t);
  if (probe) {
    send(commandPacket(Command::kEncoder, 1));
    ack_watch_.probeSent(t);
  }
  const AcknowledgementState state = ack_watch_.state(t);
  AcknowledgementState before;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_.probes_sent += probe ? 1 : 0;
    before = status_.acknowledgement;
    status_.acknowledgement = state;
    status_.unanswered_for = ack_watch_.unansweredFor(t);
  }
  if (state == before) return;
  char age[32];
  std::snprintf(age, sizeof(age), "%.2f", ack_watch_.unansweredFor(t));
  if (state == AcknowledgementState::kUnacknowledged) {
    log(LogLevel::kError, std::string("the robot does not answer for ") + age +
                              " s while its SIPs arrive: the link is one-way (driver -> robot lost); "
                              "the robot's watchdog stops it 2 s after the last command it heard");
  } else if (state == AcknowledgementState::kUnsupported) {
    log(LogLevel::kWarn, "the robot never answered ENCODER requests: a one-way link (driver -> robot lost) is "
                         "noticed only by the robot's own watchdog");
  } else if (state == AcknowledgementState::kAcknowledged && before == AcknowledgementState::kUnacknowledged) {
    log(LogLevel::kInfo, "the robot answers again: the link works both ways");
  }
}

}  // namespace aria
}  // namespace amigobot_tracking
