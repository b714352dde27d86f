// Virtual obstacle bookkeeping (core/perception/virtual_obstacles.h).
#include <gtest/gtest.h>

#include <limits>

#include "amigobot_tracking/core/perception/virtual_obstacles.h"

using namespace amigobot_tracking::core;

namespace {
VirtualObstacle obstacle(const std::string& id, double x, double y, double r) { return {id, {{x, y}, r}}; }
}  // namespace

TEST(VirtualObstacles, AddUpdateKeepOrderAndCountVersions) {
  VirtualObstacleSet set;
  const auto v0 = set.version();
  EXPECT_EQ(set.upsert(obstacle("a", 1, 0, 0.2)), VirtualObstacleSet::Change::kAdded);
  EXPECT_EQ(set.upsert(obstacle("b", 2, 0, 0.3)), VirtualObstacleSet::Change::kAdded);
  EXPECT_EQ(set.upsert(obstacle("a", 5, 5, 0.4)), VirtualObstacleSet::Change::kUpdated);
  EXPECT_GT(set.version(), v0);
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set.all()[0].id, "a");  // updated in place
  EXPECT_EQ(set.all()[0].disk.center, Eigen::Vector2d(5, 5));
  EXPECT_DOUBLE_EQ(set.all()[0].disk.radius, 0.4);
  std::vector<Disk> disks{{{9, 9}, 1.0}};
  set.appendDisks(&disks);
  ASSERT_EQ(disks.size(), 3u);
  EXPECT_EQ(disks[2].center, Eigen::Vector2d(2, 0));
}

TEST(VirtualObstacles, InvalidObstaclesAreRejectedAndChangeNothing) {
  VirtualObstacleSet set;
  set.upsert(obstacle("a", 1, 0, 0.2));
  const auto version = set.version();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const VirtualObstacle& bad : {obstacle("", 0, 0, 0.1), obstacle("a", nan, 0, 0.1), obstacle("a", 0, 0, 0.0),
                                     obstacle("c", 0, 0, -1), obstacle("a", 0, 0, nan)}) {
    std::string why;
    EXPECT_EQ(set.upsert(bad, &why), VirtualObstacleSet::Change::kRejected);
    EXPECT_FALSE(why.empty());
  }
  EXPECT_EQ(set.version(), version);
  ASSERT_EQ(set.size(), 1u);
  EXPECT_DOUBLE_EQ(set.find("a")->disk.radius, 0.2);
}

TEST(VirtualObstacles, RemoveAndClear) {
  VirtualObstacleSet set;
  set.upsert(obstacle("a", 1, 0, 0.2));
  set.upsert(obstacle("b", 2, 0, 0.2));
  set.upsert(obstacle("c", 3, 0, 0.2));
  EXPECT_TRUE(set.remove("b"));
  EXPECT_FALSE(set.remove("b"));
  EXPECT_EQ(set.find("b"), nullptr);
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set.all()[1].id, "c");
  const auto version = set.version();
  set.clear();
  EXPECT_TRUE(set.empty());
  EXPECT_GT(set.version(), version);
}

TEST(VirtualObstacles, AssignFromAListIsAllOrNothing) {
  VirtualObstacleSet set;
  set.upsert(obstacle("keep", 0, 0, 0.1));
  std::string why;
  EXPECT_FALSE(set.assign({obstacle("x", 1, 1, 0.2), obstacle("x", 2, 2, 0.2)}, &why));
  EXPECT_NE(why.find("entry 1"), std::string::npos) << why;
  EXPECT_FALSE(set.assign({obstacle("x", 1, 1, 0.2), obstacle("y", 2, 2, -0.2)}, &why));
  EXPECT_NE(why.find("radius"), std::string::npos) << why;
  ASSERT_EQ(set.size(), 1u);
  EXPECT_NE(set.find("keep"), nullptr);
  EXPECT_TRUE(set.assign({obstacle("x", 1, 1, 0.2), obstacle("y", 2, 2, 0.3)}));
  EXPECT_EQ(set.size(), 2u);
  EXPECT_EQ(set.find("keep"), nullptr);
}

TEST(VirtualObstacles, FreshIdsAreUnused) {
  VirtualObstacleSet set;
  set.upsert(obstacle("click_1", 0, 0, 0.1));
  set.upsert(obstacle("click_2", 0, 0, 0.1));
  const std::string id = set.freshId("click_");
  EXPECT_EQ(set.find(id), nullptr);
  set.upsert(obstacle(id, 0, 0, 0.1));
  EXPECT_NE(set.freshId("click_"), id);
}

TEST(VirtualObstacles, AHugeRadiusIsRefusedAndNamed) {  // issue 25: 1e6 m was accepted
  VirtualObstacleSet set;
  std::string why;
  EXPECT_EQ(set.upsert(obstacle("huge", 0, 0, 1e6), &why), VirtualObstacleSet::Change::kRejected);
  EXPECT_NE(why.find("radius of 'huge'"), std::string::npos) << why;
  EXPECT_EQ(set.upsert(obstacle("big", 0, 0, 100.0), &why), VirtualObstacleSet::Change::kAdded);
}
