// AcknowledgementWatch: does the robot still hear the driver? Driven on a synthetic clock:
// probes every 0.1 s, SIPs every 0.1 s, answers when the robot hears.
#include <gtest/gtest.h>

#include "amigobot_tracking/aria/acknowledgement_watch.h"

using amigobot_tracking::aria::AcknowledgementState;
using amigobot_tracking::aria::AcknowledgementWatch;

namespace {

constexpr double kPeriod = 0.1, kTimeout = 0.3, kSupportWait = 2.0, kStep = 0.01;

// Runs the link from `from` to `to` [s]: a probe whenever due, answered `latency` later while
// `hears`; SIPs every 0.1 s while `sips`. Returns the first time the state was unacknowledged
// (or -1).
double runLink(AcknowledgementWatch& w, double from, double to, bool hears, bool sips, double latency = 0.05) {
  double pending = -1.0, first_alarm = -1.0, next_sip = from;
  for (double t = from; t < to; t += kStep) {
    if (w.probeDue(t)) {
      w.probeSent(t);
      if (hears && pending < 0.0) pending = t + latency;
    }
    if (pending >= 0.0 && t >= pending) {
      w.answered(t);
      pending = -1.0;
    }
    if (sips && t >= next_sip) {
      w.sipArrived(t);
      next_sip += 0.1;
    }
    if (first_alarm < 0.0 && w.state(t) == AcknowledgementState::kUnacknowledged) first_alarm = t;
  }
  return first_alarm;
}

}  // namespace

TEST(AcknowledgementWatch, AnsweringRobotIsNeverUnacknowledgedEvenWithSlowAnswers) {
  AcknowledgementWatch w(kPeriod, kTimeout, kSupportWait);
  w.connected(0.0);
  EXPECT_EQ(w.state(0.0), AcknowledgementState::kUntested);
  EXPECT_LT(runLink(w, 0.0, 20.0, true, true, 0.25), 0.0);  // answers 0.25 s late: still fine
  EXPECT_EQ(w.state(20.0), AcknowledgementState::kAcknowledged);
}

TEST(AcknowledgementWatch, LostDirectionIsNamedWithinHalfASecond) {
  AcknowledgementWatch w(kPeriod, kTimeout, kSupportWait);
  w.connected(0.0);
  ASSERT_LT(runLink(w, 0.0, 5.0, true, true), 0.0);
  const double alarm = runLink(w, 5.0, 7.0, false, true);  // deaf from 5 s, SIPs still arrive
  ASSERT_GT(alarm, 0.0);
  EXPECT_LE(alarm - 5.0, kPeriod + kTimeout + 0.1 + 1e-9);  // period + timeout + one SIP cycle
  EXPECT_GE(alarm - 5.0, kTimeout);
  EXPECT_GT(w.unansweredFor(7.0), 1.5);
  // Heard again: acknowledged at the next answer.
  runLink(w, 7.0, 7.5, true, true);
  EXPECT_EQ(w.state(7.5), AcknowledgementState::kAcknowledged);
}

TEST(AcknowledgementWatch, ALateReaderWithoutNewSipsIsNoAlarm) {
  // A starved process: nothing read for 3 s (no answer, no SIP processed): no verdict, since
  // no SIP proves the robot had time to answer.
  AcknowledgementWatch w(kPeriod, kTimeout, kSupportWait);
  w.connected(0.0);
  ASSERT_LT(runLink(w, 0.0, 2.0, true, true), 0.0);
  EXPECT_LT(runLink(w, 2.0, 5.0, false, false), 0.0);
}

TEST(AcknowledgementWatch, FirmwareWithoutTheRequestIsUnsupportedAndNotProbedAgain) {
  AcknowledgementWatch w(kPeriod, kTimeout, kSupportWait);
  w.connected(0.0);
  EXPECT_LT(runLink(w, 0.0, 3.0, false, true), 0.0);
  EXPECT_EQ(w.state(3.0), AcknowledgementState::kUnsupported);
  EXPECT_FALSE(w.probeDue(3.0));
  w.connected(10.0);  // a new connection tries again
  EXPECT_TRUE(w.probeDue(10.0));
}

TEST(AcknowledgementWatch, ZeroTimeoutIsOff) {
  AcknowledgementWatch w(kPeriod, 0.0, kSupportWait);
  w.connected(0.0);
  EXPECT_FALSE(w.probeDue(1.0));
  EXPECT_EQ(w.state(1.0), AcknowledgementState::kOff);
}
