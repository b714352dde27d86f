// Other drivers' names for our parameters, in one place: a lab's config written for RosAria,
// urg_node, rplidar_ros, sick_tim, amcl or slam_toolbox carries over where a name means the
// same thing (same unit, same meaning). Read by readFields (param_reader.h) when our own name
// is unset, with an INFO line naming the mapping; with both set ours wins and the alias is
// warned. docs/ros_api.md, "Other drivers' parameter names", has the table and the names not
// carried, with why.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "amigobot_tracking/ros/param_reader.h"

namespace amigobot_tracking {
namespace ros_layer {

// The driver's: RosAria's (TicksMM -> ticks_mm, ...).
const std::vector<ParamAlias>& rosAriaAliases();
// The Laser nodelet's: urg_node's, rplidar_ros's and sick_tim's (serial_port -> port, ...).
const std::vector<ParamAlias>& laserAliases();
// The Localization nodelet's: amcl's and slam_toolbox's (initial_pose_x -> initial_pose/x, ...).
const std::vector<ParamAlias>& localizationAliases();

// The laser's address split in two, as urg_node (ip_address + ip_port, default 10940) and
// sick_tim (hostname + its own ~port, a string of digits, default "2112") give it: joined into
// our ~port "HOST:PORT" when our ~port is unset (or, for sick_tim, holds only its digits).
// `port` is what readFields read for ~port. Returns "" or "~key: reason".
std::string readSplitLaserAddress(const ros::NodeHandle& pnh, std::string* port);

}  // namespace ros_layer
}  // namespace amigobot_tracking
