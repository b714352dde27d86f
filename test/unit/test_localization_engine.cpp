// The localisation Engine (engine.h): each mode behind one interface, with what a mode cannot
// do refused with its reason, the map engine's verdict around a wrong and a searched pose, and
// a bad map file named as the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "amigobot_tracking/localization/engine.h"
#include "synthetic_room.h"
#include "temp_dir.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::localization;
using amigobot_test::roomMap;
using amigobot_test::scanAt;

class LocalizationEngine : public TempDirTest {};

TEST_F(LocalizationEngine, MappingRefusesWhatNeedsAKnownMap) {
  LocalizationConfig c;
  c.mode = "mapping";
  c.map_file = "";
  const std::unique_ptr<Engine> engine = makeEngine(c);
  EXPECT_TRUE(engine->mapGrows());
  EXPECT_FALSE(engine->measuresMatch());
  EXPECT_EQ(engine->setPose(core::Pose2{1, 0, 0}, core::Pose2()), "/initialpose ignored: mode is mapping");
  GlobalSearch search;
  EXPECT_EQ(engine->globalSearch(amigobot_test::emptyScan(10), core::Pose2(), &search),
            "global localization needs mode localization (mode is mapping)");
  std::mt19937 random(1);
  for (int i = 0; i < 5; ++i) engine->update(scanAt(amigobot_test::kLoopStart, 360, &random), core::Pose2());
  EXPECT_EQ(engine->estimate().scans, 5);
  EXPECT_TRUE(engine->estimate().localized);
  EXPECT_FALSE(engine->map().empty());
  OccupancyMap map;
  EXPECT_EQ(engine->mapToSave(&map), "") << "the path is the caller's (~map_file or ~save_map_to's)";
  EXPECT_FALSE(map.empty());
}

TEST_F(LocalizationEngine, ABadMapFileIsNamedAsTheParameter) {
  LocalizationConfig c;
  c.mode = "localization";
  c.map_file = dir_ + "/missing.yaml";
  try {
    makeEngine(c);
    FAIL() << "a missing map was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("parameter ~map_file: ", 0), 0u) << e.what();
  }
}

TEST_F(LocalizationEngine, OnAMapAWrongPoseIsNotLocalizedUntilTheSearchAndScansAgree) {
  LocalizationConfig c;
  c.mode = "localization";
  c.map_file = dir_ + "/room.yaml";
  saveMap(c.map_file, roomMap());
  const core::Pose2 truth{1.0, 0.5, 0.3};
  c.initial_pose = truth;
  const std::unique_ptr<Engine> engine = makeEngine(c);
  EXPECT_FALSE(engine->mapGrows());
  EXPECT_TRUE(engine->measuresMatch());
  OccupancyMap map;
  EXPECT_NE(engine->mapToSave(&map).find("nothing to save: mode is localization"), std::string::npos);
  std::mt19937 random(2);
  // initial_pose is applied at the first scan: good scans there make it localized.
  for (int i = 0; i < c.localized_window + 1; ++i) engine->update(scanAt(truth, 360, &random), core::Pose2());
  EXPECT_TRUE(engine->estimate().localized) << engine->estimate().not_localized;
  EXPECT_LT(std::hypot(engine->estimate().pose.x - truth.x, engine->estimate().pose.y - truth.y), 0.05);
  // A wrong /initialpose: at once not localized, and it stays so while the scans disagree.
  EXPECT_EQ(engine->setPose(core::Pose2{3.0, -0.4, 1.9}, core::Pose2()), "");
  EXPECT_FALSE(engine->estimate().localized);
  EXPECT_EQ(engine->estimate().not_localized, "initial pose set, no scan agreed with it yet");
  // The global search finds the robot; localized again only after scans agree there.
  GlobalSearch search;
  EXPECT_EQ(engine->globalSearch(scanAt(truth, 360, &random), core::Pose2(), &search), "");
  ASSERT_TRUE(search.found);
  EXPECT_FALSE(engine->estimate().localized);
  for (int i = 0; i < c.localized_window + 1; ++i) engine->update(scanAt(truth, 360, &random), core::Pose2());
  EXPECT_TRUE(engine->estimate().localized) << engine->estimate().not_localized;
  EXPECT_LT(std::hypot(engine->estimate().pose.x - truth.x, engine->estimate().pose.y - truth.y), 0.05);
}
