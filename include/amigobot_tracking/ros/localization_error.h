// Localisation error of a recorded run: the pose the stack believed (tf global -> base, as
// recorded in the bag's /tf and /tf_static) against the emulator's ground truth at the
// truth's stamps. Used by run_report to put the localiser's error beside the tracking
// metrics (make demo), and by the tests that judge localisation from the ground truth.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <string>

#include <ros/time.h>
#include <tf2_msgs/TFMessage.h>

#include "amigobot_tracking/core/support/types.h"

namespace tf2 {
class BufferCore;
}

namespace amigobot_tracking {
namespace ros_layer {

struct LocalizationErrorStats {
  size_t samples = 0;  // truth samples at which the believed pose could be looked up
  size_t missed = 0;   // truth samples with no believed pose (tf gap, before the first map -> odom)
  double rms_position = std::numeric_limits<double>::quiet_NaN();  // [m]
  double max_position = std::numeric_limits<double>::quiet_NaN();  // [m]
  double rms_heading = std::numeric_limits<double>::quiet_NaN();   // [rad]
  double max_heading = std::numeric_limits<double>::quiet_NaN();   // [rad]
};

class LocalizationErrorMeter {
 public:
  // `skip_first` [s]: truth samples this soon after the first one are not scored (the
  // localiser's start-up, before its first scan).
  LocalizationErrorMeter(std::string global_frame, std::string base_frame, double skip_first = 0.0);
  ~LocalizationErrorMeter();

  void addTf(const tf2_msgs::TFMessage& msg, bool is_static);
  void addTruth(const ros::Time& stamp, const core::Pose2& truth);
  // Scores every truth sample against the believed pose at its stamp.
  LocalizationErrorStats finish() const;

 private:
  struct Sample {
    ros::Time stamp;
    core::Pose2 truth;
  };
  std::string global_frame_, base_frame_;
  double skip_first_;
  std::unique_ptr<tf2::BufferCore> tf_;
  std::vector<Sample> truth_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
