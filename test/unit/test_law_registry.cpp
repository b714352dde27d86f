// The law registry: one name per law, every law built from it answers to its own name, and
// the facts the tools read (rho bound, robot law, obstacle velocities) agree with what the laws do.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/law/law_registry.h"
#include "amigobot_tracking/core/law/paper_controller.h"

using namespace amigobot_tracking::core;

TEST(LawRegistry, EveryCoreLawIsBuiltByNameAndAnswersToIt) {
  int built = 0;
  for (const LawEntry& entry : lawEntries()) {
    if (!entry.factory) {
      // A law of a library above core (MRPT's navigator) is refused by name until it registers.
      try {
        makeLaw(entry.name, LawSetup{});
        ADD_FAILURE() << entry.name << " was built without its provider";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(entry.provider), std::string::npos) << e.what();
      }
      continue;
    }
    const auto law = makeLaw(entry.name, LawSetup{});
    ASSERT_TRUE(law);
    EXPECT_EQ(law->name(), entry.name);
    EXPECT_EQ(law->clone()->name(), entry.name);
    // One step from a target 0.5 m ahead of the offset point: a valid command inside the diamond,
    // and a rho exactly when the registry says the law has a rho bound.
    const ControllerOutput out = law->step(0.0, PoseSample{0.0, Pose2{0.0, 0.0, 0.0}}, TargetSample{0.0, {0.8, 0.0}}, {});
    EXPECT_TRUE(out.valid) << entry.name << ": " << out.error;
    EXPECT_TRUE(law->diamond().contains(out.u, 1e-12)) << entry.name;
    EXPECT_EQ(out.rho > 0.0, entry.has_rho_bound) << entry.name;
    ++built;
  }
  EXPECT_GE(built, 4);  // paper, fixed_rho, recommended, proportional
}

TEST(LawRegistry, UnknownNamesAreRefusedNamingTheKnownOnes) {
  try {
    makeLaw("recommend", LawSetup{});
    FAIL() << "an unknown law was built";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("recommended"), std::string::npos) << e.what();
  }
  EXPECT_THROW(provideLaw("no_such_law", nullptr), std::invalid_argument);
}

// The tracking node's `law` key takes exactly the registry's robot laws, fixed_rho included.
TEST(LawRegistry, TheControllerLawKeyTakesTheRobotLaws) {
  EXPECT_EQ(controlLawNames(), robotLawNames());
  for (const std::string& name : robotLawNames()) {
    ControllerConfig c;
    c.law = name;
    EXPECT_EQ(c.validate(), "") << name;
    EXPECT_EQ(PerformanceController(c).law().name(), name);
  }
  ControllerConfig c;
  c.law = "proportional";  // a comparison baseline, not run on the robot
  EXPECT_NE(c.validate().find("law"), std::string::npos);
}

// Whether a law uses the disks' velocities is the registry's: the recommended law always (its
// barrier rows and field), the paper's laws only with moving_obstacles.
TEST(LawRegistry, ObstacleVelocitiesAreTheLawsPropertyOrTheSwitch) {
  for (const std::string& name : robotLawNames()) {
    ControllerConfig c;
    c.law = name;
    EXPECT_EQ(c.obstacleVelocities(), findLaw(name)->obstacle_velocities) << name;
    c.moving_obstacles = true;
    EXPECT_TRUE(c.obstacleVelocities()) << name;
  }
  EXPECT_TRUE(findLaw("recommended")->obstacle_velocities);
  EXPECT_FALSE(findLaw("paper")->obstacle_velocities);
  EXPECT_FALSE(findLaw("fixed_rho")->obstacle_velocities);
}

// fixed_rho is the paper's law without (13)'s relaxation: under a lasting conflict (a disk
// between the offset point and the target) the paper's rho relaxes, fixed_rho's only decays.
TEST(LawRegistry, FixedRhoIsThePaperLawWithoutRelaxation) {
  ControllerConfig c;
  PaperController paper(c), fixed(c, true);
  // p_r at 0.3 m, the disk 0.12 m inside the band (R + r + radius = 0.53 m, delta 0.25 m).
  const std::vector<Disk> wall = {Disk{{0.95, 0.0}, 0.05}};
  double rho_paper = 0.0, rho_fixed = 0.0;
  for (int k = 0; k < 20; ++k) {  // |e| = 0.6 m stays below the decaying rho: no guard
    const double t = 0.05 * k;
    const PoseSample robot{t, Pose2{0.0, 0.0, 0.0}};  // held in place: the conflict lasts
    const TargetSample target{t, {0.9, 0.0}};
    rho_paper = paper.step(t, robot, target, wall).rho;
    rho_fixed = fixed.step(t, robot, target, wall).rho;
  }
  EXPECT_EQ(fixed.name(), "fixed_rho");
  EXPECT_GT(rho_paper, rho_fixed + 1e-3);
}
