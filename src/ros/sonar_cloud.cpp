#include "amigobot_tracking/ros/sonar_cloud.h"

#include <cmath>

#include <sensor_msgs/point_cloud2_iterator.h>

namespace amigobot_tracking {
namespace ros_layer {

sensor_msgs::PointCloud2 makeSonarCloud(const std::vector<double>& ranges, const std::vector<aria::SonarPose>& sonars,
                                        double max_range, const std::string& frame, const ros::Time& stamp) {
  std::vector<std::pair<double, double>> points;
  for (std::size_t i = 0; i < ranges.size() && i < sonars.size(); ++i) {
    const double r = ranges[i];
    if (!std::isfinite(r) || r >= max_range) continue;  // no echo: nothing to place
    const aria::SonarPose& s = sonars[i];
    points.emplace_back(s.x + r * std::cos(s.yaw), s.y + r * std::sin(s.yaw));
  }
  sensor_msgs::PointCloud2 cloud;
  cloud.header.stamp = stamp;
  cloud.header.frame_id = frame;
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  modifier.setPointCloud2FieldsByString(1, "xyz");
  modifier.resize(points.size());
  sensor_msgs::PointCloud2Iterator<float> x(cloud, "x"), y(cloud, "y"), z(cloud, "z");
  for (const auto& [px, py] : points) {
    *x = static_cast<float>(px);
    *y = static_cast<float>(py);
    *z = 0.0f;
    ++x;
    ++y;
    ++z;
  }
  return cloud;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
