// The sonar ring as one sensor_msgs/PointCloud2 in base_link (RosAria's sonar_pointcloud2):
// one point (x, y, z = 0) per transducer with an echo inside its maximum range, placed
// along the transducer's axis from its pose in the robot parameters (the URDF's joints).
#pragma once

#include <string>
#include <vector>

#include <ros/time.h>
#include <sensor_msgs/PointCloud2.h>

#include "amigobot_tracking/aria/robot_params.h"

namespace amigobot_tracking {
namespace ros_layer {

// ranges [m] per transducer (NaN: none yet); readings at or beyond max_range are left out.
sensor_msgs::PointCloud2 makeSonarCloud(const std::vector<double>& ranges, const std::vector<aria::SonarPose>& sonars,
                                        double max_range, const std::string& frame, const ros::Time& stamp);

}  // namespace ros_layer
}  // namespace amigobot_tracking
