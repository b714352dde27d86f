// When two disks are one obstacle for the offset point (core/law/disk_clusters.h).
#include <gtest/gtest.h>

#include "amigobot_tracking/core/law/disk_clusters.h"

using namespace amigobot_tracking::core;

namespace {
Disk disk(double x, double y, double r) { return Disk{{x, y}, r}; }
}  // namespace

TEST(ZonesOverlap, WhenTheGrownDisksMeet) {
  // Centres 2 m apart, radii 0.2 and 0.3: the zones meet at reach 0.75.
  EXPECT_TRUE(zonesOverlap(disk(0, 0, 0.2), disk(2, 0, 0.3), 0.75));
  EXPECT_FALSE(zonesOverlap(disk(0, 0, 0.2), disk(2, 0, 0.3), 0.7499));
  EXPECT_TRUE(zonesOverlap(disk(0, 0, 0.2), disk(0.1, 0, 0.1), 0.0));  // the disks themselves overlap
  EXPECT_TRUE(zonesOverlap(disk(1, 1, 0.2), disk(1, 1, 0.2), 0.0));    // the same disk
  // Symmetric, and in any direction.
  EXPECT_EQ(zonesOverlap(disk(0, 0, 0.1), disk(0.6, 0.8, 0.1), 0.4),
            zonesOverlap(disk(0.6, 0.8, 0.1), disk(0, 0, 0.1), 0.4));
  EXPECT_TRUE(zonesOverlap(disk(0, 0, 0.1), disk(0.6, 0.8, 0.1), 0.4));   // 1.0 <= 0.2 + 0.8
  EXPECT_FALSE(zonesOverlap(disk(0, 0, 0.1), disk(0.6, 0.8, 0.1), 0.39));
}

TEST(ZonesOverlap, RingScenarioNeighboursWithTheBodySafeRadius) {
  // config/scenarios/ring.yaml: 0.08 m disks about 1.57 m apart; R + r + delta = 0.73 m.
  EXPECT_TRUE(zonesOverlap(disk(1.848, 0.765, 0.08), disk(0.823, 1.986, 0.08), 0.73));
  EXPECT_FALSE(zonesOverlap(disk(1.848, 0.765, 0.08), disk(-0.765, 1.848, 0.08), 0.73));
  // The paper's radius (R = 0.18) and delta = 0.25: apart.
  EXPECT_FALSE(zonesOverlap(disk(1.848, 0.765, 0.08), disk(0.823, 1.986, 0.08), 0.43));
}
