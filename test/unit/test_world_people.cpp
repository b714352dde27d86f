// People in the world file (world/world.h): moving disks read with their path, refused with
// file:line:key, written back, and placed by worldAt where every reader (ray casts, sonar,
// clearances) sees them at the same instant.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/world/geometry.h"
#include "amigobot_tracking/world/raycast.h"
#include "amigobot_tracking/world/world.h"

using namespace amigobot_tracking;
using world::parseWorld;
using world::World;

namespace {

// A person 0.25 m wide crossing the x axis at x = 2 upwards at 0.5 m/s from t = 10 s.
const char* kCrossing = R"(obstacles:
  - {center: [5.0, 0.0], radius: 0.1}
people:
  - radius: 0.25
    start: [2.0, -2.0]
    start_time: 10.0
    legs:
      - {duration: 8.0, velocity: [0.0, 0.5]}
)";

std::string parseErrorFor(const std::string& text) {
  try {
    parseWorld(text, "w.yaml");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(WorldPeople, ReadsAPersonAndItsPath) {
  const World w = parseWorld(kCrossing, "w.yaml");
  ASSERT_EQ(w.people.size(), 1u);
  EXPECT_DOUBLE_EQ(w.people[0].radius, 0.25);
  EXPECT_DOUBLE_EQ(w.people[0].motion.start_time, 10.0);
  ASSERT_EQ(w.people[0].motion.legs.size(), 1u);
  EXPECT_DOUBLE_EQ(w.people[0].motion.legs[0].velocity.y(), 0.5);
  EXPECT_FALSE(w.people[0].motion.repeat);
  EXPECT_FALSE(w.empty());
  EXPECT_TRUE(world::validateWorld(w).empty());
}

TEST(WorldPeople, WorldAtPlacesThemOnTheEmulatorClock) {
  const World w = parseWorld(kCrossing, "w.yaml");
  const World before = world::worldAt(w, 5.0), crossing = world::worldAt(w, 14.0), after = world::worldAt(w, 30.0);
  ASSERT_EQ(crossing.obstacles.size(), 2u) << "the fixed disk, then the person";
  EXPECT_TRUE(crossing.people.empty());
  EXPECT_EQ(before.obstacles[1].center, Eigen::Vector2d(2.0, -2.0)) << "stands at its start until start_time";
  EXPECT_NEAR(crossing.obstacles[1].center.y(), 0.0, 1e-12);
  EXPECT_NEAR(after.obstacles[1].center.y(), 2.0, 1e-12) << "stands where the last leg ended";
  EXPECT_DOUBLE_EQ(crossing.obstacles[1].radius, 0.25);
}

TEST(WorldPeople, TheLaserSeesThePersonOnlyWhenItIsThere) {
  // A beam from the origin along +x: the person is on it at t = 14 s only (then at 2 m - r).
  const World w = parseWorld(kCrossing, "w.yaml");
  core::ScanGeometry beam;
  beam.angle_min = 0.0;
  beam.angle_increment = 0.01;
  beam.range_min = 0.05;
  beam.range_max = 8.0;
  const core::Pose2 sensor{0.0, 0.0, 0.0};
  EXPECT_NEAR(world::raycastScan(sensor, world::worldAt(w, 14.0), beam, 1)[0], 1.75, 1e-6);
  EXPECT_NEAR(world::raycastScan(sensor, world::worldAt(w, 5.0), beam, 1)[0], 4.9, 1e-6) << "only the fixed disk";
  EXPECT_NEAR(world::clearance(world::worldAt(w, 14.0), {1.5, 0.0}, 0.18), 0.5 - 0.25 - 0.18, 1e-12)
      << "a body beside the person: the clearance counts it";
}

TEST(WorldPeople, BadPeopleAreNamedWithFileLineAndKey) {
  EXPECT_EQ(parseErrorFor("people:\n  - {start: [0, 0]}\n"), "w.yaml:2: people[0].radius: missing: a radius > 0 in metres");
  EXPECT_EQ(parseErrorFor("people:\n  - {radius: 0.2}\n"),
            "w.yaml:2: people[0].start: missing: where it stands first, [x, y] in metres");
  EXPECT_EQ(parseErrorFor("people:\n  - {radius: 0.2, start: [0, 0], legs: [{duration: 0, velocity: [1, 0]}]}\n"),
            "w.yaml:2: people[0].legs[0].duration: 0 is not a finite duration > 0");
  EXPECT_EQ(parseErrorFor("people:\n  - {radius: 0.2, start: [0, 0], legs: [{duration: 1, velocity: [1]}]}\n"),
            "w.yaml:2: people[0].legs[0].velocity: expected [vx, vy] in m/s (finite)");
  EXPECT_EQ(parseErrorFor("people:\n  - {radius: 0.2, start: [0, 0], speed: 1}\n"),
            "w.yaml:2: people[0].speed: unknown key (misspelt?)");
  EXPECT_EQ(parseErrorFor("people:\n  - {radius: 0.2, start: [0, 0], repeat: true, legs: [{duration: 1, velocity: [1, 0]}]}\n")
                .rfind("w.yaml:2: people[0].repeat: the legs end 1 m from the start", 0),
            0u);
  EXPECT_EQ(parseErrorFor("people:\n  - {radius: -1, start: [0, 0]}\n"), "w.yaml:2: people[0].radius: expected a radius > 0 in metres");
}

TEST(WorldPeople, YamlRoundTripsAndValidateNamesABadPerson) {
  World w = parseWorld(kCrossing, "w.yaml");
  w.people[0].motion.legs.push_back({8.0, {0.0, -0.5}});
  w.people[0].motion.repeat = true;
  const World back = parseWorld(world::worldYaml(w), "back.yaml");
  ASSERT_EQ(back.people.size(), 1u);
  EXPECT_EQ(back.people[0].motion.legs.size(), 2u);
  EXPECT_TRUE(back.people[0].motion.repeat);
  EXPECT_EQ(world::worldAt(back, 20.0).obstacles[1].center, world::worldAt(w, 20.0).obstacles[1].center);
  w.people[0].radius = 0.0;
  EXPECT_EQ(world::validateWorld(w), "people[0].radius: expected a radius > 0 in metres");
}
