// The world file reader (world/world.h): the shipped example, and errors that name the
// file, the line and the key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/world/world.h"

using amigobot_tracking::world::loadWorld;
using amigobot_tracking::world::World;

namespace {

// The error loadWorld gives for a world file with `text`, or "" when it accepts it.
std::string errorFor(const std::string& text) {
  const std::string path = "/tmp/amigobot_world_" + std::to_string(::getpid()) + ".yaml";
  std::ofstream(path) << text;
  std::string error;
  try {
    loadWorld(path);
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  std::remove(path.c_str());
  return error;
}

}  // namespace

TEST(World, ShippedExampleLoads) {
  const World w = loadWorld(std::string(AMIGOBOT_SOURCE_DIR) + "/config/worlds/emulator_example.yaml");
  ASSERT_EQ(w.obstacles.size(), 3u);
  EXPECT_DOUBLE_EQ(w.obstacles[0].center.x(), 1.5);
  EXPECT_DOUBLE_EQ(w.obstacles[2].radius, 0.3);
  ASSERT_TRUE(w.initial_pose);
  EXPECT_DOUBLE_EQ(w.initial_pose->x, 0.0);
}

TEST(World, BadEntriesAreNamedWithTheirLine) {
  const std::string e = errorFor("obstacles:\n  - {center: [1, 2], radius: 0.1}\n  - {center: [1], radius: 0.1}\n");
  EXPECT_NE(e.find("obstacles[1]"), std::string::npos) << e;
  EXPECT_NE(e.find(":3:"), std::string::npos) << e;
  EXPECT_NE(e.find("/tmp/amigobot_world_"), std::string::npos) << e;
  EXPECT_NE(errorFor("obstacles:\n  - {center: [1, 2], radius: -0.1}\n").find("obstacles[0].radius"),
            std::string::npos);
  EXPECT_NE(errorFor("initial_pose: [1, 2]\n").find("initial_pose"), std::string::npos);
  EXPECT_NE(errorFor("obstacles: {center: [1, 2]}\n").find("obstacles: expected a list"), std::string::npos);
  EXPECT_THROW(loadWorld("/nonexistent/world.yaml"), std::runtime_error);
}

TEST(World, UnknownKeysAreRefused) {
  const std::string top = errorFor("initial_pose: [0, 0, 0]\nobstacle: []\n");
  EXPECT_NE(top.find(":2: obstacle: unknown key"), std::string::npos) << top;
  const std::string inner = errorFor("obstacles:\n  - {center: [1, 2], radius: 0.1, height: 1}\n");
  EXPECT_NE(inner.find("obstacles[0].height: unknown key"), std::string::npos) << inner;
}

TEST(World, KeysAreOptional) {
  EXPECT_EQ(errorFor("obstacles: []\n"), "");
  EXPECT_EQ(errorFor("initial_pose: [1, 2, 0.5]\n"), "");
  EXPECT_NE(errorFor(""), "") << "an empty file is no world";
}
