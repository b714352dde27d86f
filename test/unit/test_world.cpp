// The world file reader (world/world.h): the shipped example, and errors that name the
// file, the line and the key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/world/world.h"

using amigobot_tracking::world::loadWorld;
using amigobot_tracking::world::validateWorld;
using amigobot_tracking::world::World;
using amigobot_tracking::world::worldYaml;

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

TEST(World, WallsAndPolygonsLoad) {
  const std::string path = "/tmp/amigobot_world_walls_" + std::to_string(::getpid()) + ".yaml";
  std::ofstream(path) << "walls:\n"
                         "  - {from: [0, 0], to: [4, 0]}\n"
                         "  - {points: [[0, 1], [0, 3], [2, 3]]}\n"
                         "polygons:\n"
                         "  - {points: [[1, 1], [2, 1], [2, 2], [1, 2]]}\n";
  const World w = loadWorld(path);
  std::remove(path.c_str());
  ASSERT_EQ(w.walls.size(), 3u) << "a chain of 3 points is 2 segments";
  EXPECT_EQ(w.walls[0].to, Eigen::Vector2d(4.0, 0.0));
  EXPECT_EQ(w.walls[2].from, Eigen::Vector2d(0.0, 3.0));
  EXPECT_EQ(w.walls[2].to, Eigen::Vector2d(2.0, 3.0));
  ASSERT_EQ(w.polygons.size(), 1u);
  EXPECT_EQ(w.polygons[0].points.size(), 4u);
  EXPECT_TRUE(w.obstacles.empty());
  EXPECT_FALSE(w.initial_pose);
}

TEST(World, BadWallsAndPolygonsAreNamedWithTheirLine) {
  const auto expect = [](const std::string& text, const std::string& located) {
    const std::string e = errorFor(text);
    EXPECT_NE(e.find(located), std::string::npos) << "want '" << located << "' in: " << e;
  };
  expect("walls:\n  - {from: [0, 0], to: [1, 0]}\n  - {from: [2, 2], to: [2, 2]}\n", ":3: walls[1]: degenerate");
  expect("walls:\n  - {from: [0, 0], to: [1, .nan]}\n", ":2: walls[0].to: expected [x, y]");
  expect("walls:\n  - {from: [0, 0], to: [1, .inf]}\n", "walls[0].to: expected [x, y] in metres (finite)");
  expect("walls:\n  - {from: [0, 0]}\n", "walls[0]: expected {from");
  expect("walls:\n  - {from: [0, 0], to: [1, 0], points: [[0, 0], [1, 1]]}\n", "walls[0]: either from/to or points");
  expect("walls:\n  - {points: [[0, 0]]}\n", "walls[0].points: a wall needs at least 2 points");
  expect("walls:\n  - {points: [[0, 0], [1, 0], [1, 0]]}\n", "walls[0].points[1]: degenerate");
  expect("walls:\n  - {form: [0, 0], to: [1, 0]}\n", ":2: walls[0].form: unknown key");
  expect("walls: {from: [0, 0], to: [1, 0]}\n", ":1: walls: expected a list");
  expect("polygons:\n  - {points: [[0, 0], [1, 0]]}\n", ":2: polygons[0].points: a polygon needs at least 3 points");
  expect("polygons:\n  - {points: [[0, 0], [1, 0], [2, 0]]}\n", "polygons[0].points: degenerate polygon");
  expect("polygons:\n  - {points: [[0, 0], [1, 0], [1, 0], [0, 1]]}\n", "polygons[0].points[1]: repeats");
  expect("polygons:\n  - {points: [[0, 0], [1, 0], [1, .nan]]}\n", "polygons[0].points[2]: expected [x, y]");
  expect("polygons:\n  - {points: [[0, 0], [1, 0], [1, 1]], height: 1}\n", "polygons[0].height: unknown key");
  expect("polygons:\n  - [[0, 0], [1, 0], [1, 1]]\n", "polygons[0]: expected {points");
}

TEST(World, ValidateNamesTheBadShape) {
  World w;
  EXPECT_EQ(validateWorld(w), "");
  w.walls = {{{0.0, 0.0}, {1.0, 0.0}}, {{1.0, 1.0}, {1.0, 1.0}}};
  EXPECT_EQ(validateWorld(w).rfind("walls[1]: degenerate", 0), 0u) << validateWorld(w);
  w.walls.pop_back();
  w.polygons = {{{{0.0, 0.0}, {1.0, 0.0}}}};
  EXPECT_EQ(validateWorld(w).rfind("polygons[0].points: ", 0), 0u) << validateWorld(w);
  w.polygons.clear();
  w.obstacles = {{{0.0, std::nan("")}, 0.1}};
  EXPECT_EQ(validateWorld(w).rfind("obstacles[0].center: ", 0), 0u) << validateWorld(w);
}

TEST(World, YamlRoundTrips) {
  World w;
  w.initial_pose = amigobot_tracking::core::Pose2{0.1, -0.2, 0.3};
  w.obstacles = {{{1.0 / 3.0, 2.0}, 0.15}};
  w.walls = {{{-1.0, -1.0}, {5.0, -1.0}}};
  w.polygons = {{{{1.0, 1.0}, {1.5, 1.0}, {1.2, 1.7}}}};
  const std::string path = "/tmp/amigobot_world_round_" + std::to_string(::getpid()) + ".yaml";
  std::ofstream(path) << worldYaml(w);
  const World back = loadWorld(path);
  std::remove(path.c_str());
  ASSERT_TRUE(back.initial_pose);
  EXPECT_DOUBLE_EQ(back.initial_pose->theta, 0.3);
  ASSERT_EQ(back.obstacles.size(), 1u);
  EXPECT_DOUBLE_EQ(back.obstacles[0].center.x(), 1.0 / 3.0);
  ASSERT_EQ(back.walls.size(), 1u);
  EXPECT_EQ(back.walls[0].to, w.walls[0].to);
  ASSERT_EQ(back.polygons.size(), 1u);
  EXPECT_EQ(back.polygons[0].points, w.polygons[0].points);
  EXPECT_EQ(errorFor(worldYaml(World{})), "") << "an empty world is written as a valid file";
}

TEST(World, ShippedWorldsLoad) {
  for (const char* name : {"demo_5_3", "emulator_example", "lab"}) {
    const std::string path = std::string(AMIGOBOT_SOURCE_DIR) + "/config/worlds/" + name + ".yaml";
    EXPECT_NO_THROW(loadWorld(path)) << path;
  }
  const World lab = loadWorld(std::string(AMIGOBOT_SOURCE_DIR) + "/config/worlds/lab.yaml");
  EXPECT_GE(lab.walls.size(), 4u);
  EXPECT_GE(lab.polygons.size(), 1u);
  EXPECT_TRUE(lab.initial_pose);
}
