// Is a rigid transform (a tf sample, an /initialpose) usable? Poses are checked where they
// enter the stack: a NaN or infinite coordinate, or a rotation that is not a unit quaternion
// (the all-zero quaternion of a hand-written message), is refused by name instead of being
// passed on to be published as NaN. Std only.
#pragma once

#include <string>

namespace amigobot_tracking {
namespace core {

// A quaternion whose norm is within this of 1 is taken (and normalised by whoever uses it);
// further off it is refused. tf2 itself refuses |norm^2 - 1| > 0.01, so this is stricter than
// tf2 and loose enough for float32 round-off (1e-7).
constexpr double kUnitQuaternionTolerance = 1e-3;

struct Translation3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
struct Quaternion4 {
  double x = 0.0, y = 0.0, z = 0.0, w = 1.0;
};

// "" when usable, else which field is wrong and how: "translation x is nan",
// "rotation is not a unit quaternion (norm 0.000)".
std::string transformProblem(const Translation3& translation, const Quaternion4& rotation);

// The unit quaternion of `q` (call only on one transformProblem accepted).
Quaternion4 normalised(const Quaternion4& q);

}  // namespace core
}  // namespace amigobot_tracking
