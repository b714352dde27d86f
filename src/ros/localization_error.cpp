#include "amigobot_tracking/ros/localization_error.h"

#include <algorithm>
#include <cmath>

#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>
#include <tf2/utils.h>

namespace amigobot_tracking {
namespace ros_layer {

namespace {
// A recorded run is scored as a whole: the buffer keeps every transform of the bag.
const ros::Duration kWholeRun(24.0 * 3600.0);

double wrapped(double a) { return std::atan2(std::sin(a), std::cos(a)); }
}  // namespace

LocalizationErrorMeter::LocalizationErrorMeter(std::string global_frame, std::string base_frame, double skip_first)
    : global_frame_(std::move(global_frame)),
      base_frame_(std::move(base_frame)),
      skip_first_(skip_first),
      tf_(std::make_unique<tf2::BufferCore>(kWholeRun)) {}

LocalizationErrorMeter::~LocalizationErrorMeter() = default;

void LocalizationErrorMeter::addTf(const tf2_msgs::TFMessage& msg, bool is_static) {
  for (const geometry_msgs::TransformStamped& t : msg.transforms) {
    try {
      tf_->setTransform(t, "bag", is_static);
    } catch (const tf2::TransformException&) {
      // A malformed transform in the bag (empty frame, NaN): it simply is not believed.
    }
  }
}

void LocalizationErrorMeter::addTruth(const ros::Time& stamp, const core::Pose2& truth) {
  truth_.push_back({stamp, truth});
}

LocalizationErrorStats LocalizationErrorMeter::finish() const {
  LocalizationErrorStats out;
  if (truth_.empty()) return out;
  const ros::Time first = truth_.front().stamp + ros::Duration(skip_first_);
  double sum_p2 = 0.0, sum_h2 = 0.0, max_p = 0.0, max_h = 0.0;
  for (const Sample& s : truth_) {
    if (s.stamp < first) continue;
    geometry_msgs::TransformStamped believed;
    try {
      believed = tf_->lookupTransform(global_frame_, base_frame_, s.stamp);
    } catch (const tf2::TransformException&) {
      ++out.missed;
      continue;
    }
    const double dx = believed.transform.translation.x - s.truth.x;
    const double dy = believed.transform.translation.y - s.truth.y;
    const double dp = std::hypot(dx, dy);
    const double dh = std::fabs(wrapped(tf2::getYaw(believed.transform.rotation) - s.truth.theta));
    if (!std::isfinite(dp) || !std::isfinite(dh)) {
      ++out.missed;
      continue;
    }
    sum_p2 += dp * dp;
    sum_h2 += dh * dh;
    max_p = std::max(max_p, dp);
    max_h = std::max(max_h, dh);
    ++out.samples;
  }
  if (out.samples == 0) return out;
  const double n = static_cast<double>(out.samples);
  out.rms_position = std::sqrt(sum_p2 / n);
  out.rms_heading = std::sqrt(sum_h2 / n);
  out.max_position = max_p;
  out.max_heading = max_h;
  return out;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
