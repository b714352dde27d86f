// cmd_vel arbitration (core/supervision/command_lock.h): one source drives, others are refused.
#include <gtest/gtest.h>

#include <limits>

#include "amigobot_tracking/core/supervision/command_lock.h"

using amigobot_tracking::core::CommandLock;

TEST(CommandLock, TheFirstPublisherKeepsTheLockWhileItSends) {
  CommandLock lock("", 1.0);
  EXPECT_EQ(lock.owner(), "");
  EXPECT_TRUE(lock.accept("/tracking", 0.0));
  EXPECT_EQ(lock.owner(), "/tracking");
  // A second publisher at 100 Hz between tracking's 20 Hz commands: never taken.
  for (int i = 1; i < 500; ++i) {
    const double t = i * 0.01;
    EXPECT_FALSE(lock.accept("/intruder", t)) << t;
    if (i % 5 == 0) {
      EXPECT_TRUE(lock.accept("/tracking", t)) << t;
    }
  }
  EXPECT_EQ(lock.owner(), "/tracking");
}

TEST(CommandLock, TheLockPassesOnOnlyAfterTheHolderFellSilent) {
  CommandLock lock("", 1.0);
  EXPECT_TRUE(lock.accept("/tracking", 10.0));
  EXPECT_FALSE(lock.accept("/teleop", 10.9));
  EXPECT_FALSE(lock.accept("/teleop", 11.0));  // exactly release_after: still held
  EXPECT_TRUE(lock.accept("/teleop", 11.1));
  EXPECT_EQ(lock.owner(), "/teleop");
  EXPECT_FALSE(lock.accept("/tracking", 11.2));  // the old holder waits its turn too
}

TEST(CommandLock, AConfiguredSourceIsTheOnlyOneEver) {
  CommandLock lock("/tracking", 1.0);
  EXPECT_TRUE(lock.configured());
  EXPECT_EQ(lock.owner(), "/tracking");
  EXPECT_FALSE(lock.accept("/intruder", 0.0));  // first, yet refused
  EXPECT_FALSE(lock.accept("/intruder", 100.0));
  EXPECT_TRUE(lock.accept("/tracking", 100.1));
}

TEST(CommandLock, ANonFiniteTimeNeverReleasesTheLock) {
  CommandLock lock("", 1.0);
  EXPECT_TRUE(lock.accept("/tracking", 0.0));
  EXPECT_FALSE(lock.accept("/intruder", std::numeric_limits<double>::quiet_NaN()));
  EXPECT_EQ(lock.owner(), "/tracking");
}
