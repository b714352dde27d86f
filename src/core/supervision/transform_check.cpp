#include "amigobot_tracking/core/supervision/transform_check.h"

#include <cmath>
#include <sstream>

namespace amigobot_tracking {
namespace core {

namespace {

std::string notFinite(const char* field, double value) {
  std::ostringstream why;
  why << field << " is " << value;  // "nan", "inf" or "-inf"
  return why.str();
}

}  // namespace

std::string transformProblem(const Translation3& t, const Quaternion4& q) {
  const struct {
    const char* name;
    double value;
  } fields[] = {{"translation x", t.x}, {"translation y", t.y}, {"translation z", t.z}, {"rotation x", q.x},
                {"rotation y", q.y},    {"rotation z", q.z},    {"rotation w", q.w}};
  for (const auto& f : fields) {
    if (!std::isfinite(f.value)) return notFinite(f.name, f.value);
  }
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!(std::abs(norm - 1.0) <= kUnitQuaternionTolerance)) {
    std::ostringstream why;
    why.precision(3);
    why << std::fixed << "rotation is not a unit quaternion (norm " << norm << ", tolerance "
        << kUnitQuaternionTolerance << ")";
    return why.str();
  }
  return "";
}

Quaternion4 normalised(const Quaternion4& q) {
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return {q.x / norm, q.y / norm, q.z / norm, q.w / norm};
}

}  // namespace core
}  // namespace amigobot_tracking
