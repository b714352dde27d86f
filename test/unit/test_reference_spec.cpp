// The one reference factory (core/reference/reference_spec.h): each type builds its curve
// from the spec, and a spec out of its bounds is refused naming the key.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "amigobot_tracking/core/reference/reference_spec.h"

using namespace amigobot_tracking::core;

namespace {

std::string refusal(const ReferenceSpec& spec) {
  try {
    makeReference(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ReferenceSpec, EachTypeBuildsItsCurve) {
  ReferenceSpec spec;
  spec.type = "rose";
  spec.amplitude = 3.0;
  spec.k = 3.0;
  spec.period_scale = 2.0;
  const RoseReference rose(3.0, 3.0, 2.0);
  EXPECT_TRUE(makeReference(spec)->at(1.7).position.isApprox(rose.at(1.7).position));

  spec.type = "circle";
  spec.center = Eigen::Vector2d(1.0, -1.0);
  spec.radius = 2.0;
  spec.period = 20.0;
  EXPECT_NEAR(makeReference(spec)->at(0.0).position.x(), 3.0, 1e-12);

  spec.waypoints = {{0.0, 0.0}, {2.0, 0.0}};
  spec.type = "spline";
  spec.duration = 10.0;
  EXPECT_NEAR(makeReference(spec)->at(10.0).position.x(), 2.0, 1e-9);
  spec.type = "waypoints";
  spec.speed = 0.5;
  EXPECT_NEAR(makeReference(spec)->at(2.0).position.x(), 1.0, 1e-9);
}

TEST(ReferenceSpec, RefusesNamingTheKey) {
  ReferenceSpec spec;
  spec.type = "lemniscate";
  EXPECT_EQ(refusal(spec).rfind("type:", 0), 0u) << refusal(spec);
  spec.type = "rose";
  spec.period_scale = 0.0;
  EXPECT_EQ(refusal(spec).rfind("period_scale:", 0), 0u) << refusal(spec);
  spec = ReferenceSpec();
  spec.type = "spline";
  spec.waypoints = {{0.0, 0.0}};
  EXPECT_NE(refusal(spec).find("at least 2 waypoints"), std::string::npos) << refusal(spec);
}

// The list of curves names only keys of the table, each curve's own; types are listed once.
TEST(ReferenceSpec, EachCurvesKeysAreRowsOfTheTable) {
  for (const ReferenceCurve& curve : referenceCurves()) {
    for (const auto* keys : {&curve.required, &curve.optional})
      for (const std::string& key : *keys) {
        bool found = false;
        for (const auto& row : referenceFields()) found = found || row.key == key;
        EXPECT_TRUE(found) << curve.type << ": " << key;
        EXPECT_NE(key, "type");
      }
    EXPECT_EQ(&referenceCurve(curve.type), &curve);
  }
  EXPECT_EQ(referenceTypes().size(), referenceCurves().size());
  try {
    referenceCurve("lemniscate");
    FAIL() << "no refusal";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'lemniscate' (rose, circle, spline, waypoints)"), std::string::npos) << e.what();
  }
}

