// MasterPresence: what polls of the ROS master say (lost, back, a new master).
#include <gtest/gtest.h>

#include "amigobot_tracking/ros/master_presence.h"

using amigobot_tracking::ros_layer::MasterPresence;
using amigobot_tracking::ros_layer::MasterOutage;
using Change = MasterPresence::Change;

TEST(MasterPresence, RestartedMasterIsANewOne) {
  MasterPresence p;
  EXPECT_EQ(p.observe(0.0, std::string("100")), Change::kNone);  // the master we started with
  EXPECT_EQ(p.observe(0.1, std::string("100")), Change::kNone);
  EXPECT_DOUBLE_EQ(p.unreachableFor(0.2), 0.0);
  EXPECT_EQ(p.observe(0.2, std::nullopt), Change::kNone);  // one failed poll: not lost yet
  EXPECT_TRUE(p.reachable());
  EXPECT_EQ(p.observe(0.3, std::nullopt), Change::kLost);
  EXPECT_EQ(p.observe(0.4, std::nullopt), Change::kNone);
  EXPECT_FALSE(p.reachable());
  EXPECT_NEAR(p.unreachableFor(0.9), 0.8, 1e-12);  // since the last answer
  EXPECT_EQ(p.observe(1.0, std::string("200")), Change::kNewMaster);
  EXPECT_TRUE(p.reachable());
  EXPECT_DOUBLE_EQ(p.unreachableFor(1.0), 0.0);
}

TEST(MasterPresence, SameMasterAfterAHiccupIsBackNotNew) {
  MasterPresence p;
  p.observe(0.0, std::string("100"));
  EXPECT_EQ(p.observe(0.1, std::nullopt), Change::kNone);
  EXPECT_EQ(p.observe(0.2, std::nullopt), Change::kLost);
  EXPECT_EQ(p.observe(0.3, std::string("100")), Change::kBack);
}

// A poll that timed out while the master was busy (it answers the next one): the master was
// never lost, and nothing that watches unreachableFor sees a gap. Before, that one poll made
// the master unreachable for 0.52 s and the tracking nodelet disabled itself for good.
TEST(MasterPresence, OneSlowAnswerIsNotALostMaster) {
  MasterPresence p;
  p.observe(0.0, std::string("100"));
  EXPECT_EQ(p.observe(0.52, std::nullopt), Change::kNone);  // sent at 0.2, timed out after 0.3 s
  EXPECT_TRUE(p.reachable());
  EXPECT_DOUBLE_EQ(p.unreachableFor(0.52), 0.0);
  EXPECT_EQ(p.observe(0.75, std::string("100")), Change::kNone);
}

TEST(MasterPresence, RestartBetweenTwoPollsIsStillSeen) {
  MasterPresence p;
  p.observe(0.0, std::string("100"));
  EXPECT_EQ(p.observe(0.1, std::string("300")), Change::kNewMaster);
}

TEST(MasterPresence, NeverReachedIsNotUnreachableForLong) {
  MasterPresence p;
  EXPECT_EQ(p.observe(0.0, std::nullopt), Change::kNone);
  EXPECT_DOUBLE_EQ(p.unreachableFor(100.0), 0.0);
  EXPECT_FALSE(p.everReached());
}

// The driver's and the tracking node's rule, fed from the watch as they poll it.
using Action = MasterOutage::Action;

// A master that was busy for 1 s (three stacks starting on two cores) and answers again with
// the same pid: the robot stopped, and goes on by itself. Before, the motors stayed off until
// someone called enable_motors, and an end-to-end test waited 60 s for them.
TEST(MasterOutage, TheSameMasterBackResumes) {
  MasterOutage o;
  const std::optional<std::string> pid("100");
  EXPECT_EQ(o.check(true, 0.0, pid, 0.5), Action::kNone);
  EXPECT_EQ(o.check(false, 0.4, pid, 0.5), Action::kNone);  // not yet past the timeout
  EXPECT_EQ(o.check(false, 0.6, pid, 0.5), Action::kStop);
  EXPECT_TRUE(o.stopped());
  EXPECT_EQ(o.check(false, 0.9, pid, 0.5), Action::kNone);  // stopped once, not again
  EXPECT_EQ(o.check(true, 0.0, pid, 0.5), Action::kResume);
  EXPECT_FALSE(o.stopped());
  EXPECT_EQ(o.check(true, 0.0, pid, 0.5), Action::kNone);
}

// A restarted master (another pid) knows nothing of who commanded the robot: stay stopped.
TEST(MasterOutage, ANewMasterLeavesTheRobotStopped) {
  MasterOutage o;
  EXPECT_EQ(o.check(false, 0.7, std::string("100"), 0.5), Action::kStop);
  EXPECT_EQ(o.check(true, 0.0, std::string("300"), 0.5), Action::kStayStopped);
  EXPECT_FALSE(o.stopped());
  // The next outage is judged against the new master.
  EXPECT_EQ(o.check(false, 0.7, std::string("300"), 0.5), Action::kStop);
  EXPECT_EQ(o.check(true, 0.0, std::string("300"), 0.5), Action::kResume);
}

// A stop before any master answered (no identity known) never resumes by itself.
TEST(MasterOutage, NoKnownMasterIsNeverTheSameOne) {
  MasterOutage o;
  EXPECT_EQ(o.check(false, 0.7, std::nullopt, 0.5), Action::kStop);
  EXPECT_EQ(o.check(true, 0.0, std::string("100"), 0.5), Action::kStayStopped);
}

// The watch's own rule and this one together: one slow poll is not an outage at all.
TEST(MasterOutage, OneSlowPollDoesNotStop) {
  MasterPresence p;
  MasterOutage o;
  p.observe(0.0, std::string("100"));
  p.observe(0.52, std::nullopt);
  EXPECT_EQ(o.check(p.reachable(), p.unreachableFor(0.6), p.identity(), 0.5), Action::kNone);
}
