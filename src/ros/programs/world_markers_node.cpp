// world_markers: publishes the world file (disks, walls, polygons) once, latched, as
// visualization_msgs/MarkerArray on `world_markers`, for rviz. A world with people is
// redrawn on each tick of the emulator's clock (ground_truth_clock, at most 10 Hz) with each
// person where it is then.
// Parameters (private): include/amigobot_tracking/ros/world_markers.h (WorldMarkersConfig).
#include <cmath>

#include <ros/ros.h>
#include <sensor_msgs/TimeReference.h>

#include "amigobot_tracking/ros/master_watch.h"
#include "amigobot_tracking/ros/node_command_line.h"
#include "amigobot_tracking/ros/param_reader.h"
#include "amigobot_tracking/ros/world_markers.h"

using namespace amigobot_tracking;

const ros_layer::NodeHelp kHelp{
    "Publishes the world file (disks, walls, polygons) latched as visualization_msgs/MarkerArray on "
    "`world_markers`, for rviz.",
    "include/amigobot_tracking/ros/world_markers.h (WorldMarkersConfig)."};

int main(int argc, char** argv) {
  ros_layer::initNode(argc, argv, "world_markers", kHelp);
  ros::NodeHandle nh, pnh("~");
  // A restarted master learns this node's topics again, as the nodelets' (ros/master_watch.h).
  const auto master_watch = ros_layer::MasterWatch::shared();
  ros_layer::WorldMarkersConfig config;
  if (!ros_layer::configLoaded("world_markers", ros_layer::readParams(pnh, ros_layer::worldMarkersFields(), &config))) {
    return 1;
  }
  world::World room;
  try {
    room = world::loadWorld(config.world_file);
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("world_markers: " << e.what());
    return 1;
  }
  ros::Publisher pub = nh.advertise<visualization_msgs::MarkerArray>("world_markers", 1, true);
  pub.publish(ros_layer::worldMarkers(world::worldAt(room, 0.0), config));
  // People move on the emulator's clock (world/world.h): redrawn where they are, at most 10 Hz.
  ros::Subscriber clock_sub;
  double last_drawn = -1.0;
  if (!room.people.empty()) {
    clock_sub = nh.subscribe<sensor_msgs::TimeReference>(
        "ground_truth_clock", 5, [&](const sensor_msgs::TimeReference::ConstPtr& clock) {
          const double t = clock->time_ref.toSec();
          if (last_drawn >= 0.0 && std::abs(t - last_drawn) < 0.1) return;
          last_drawn = t;
          pub.publish(ros_layer::worldMarkers(world::worldAt(room, t), config));
        });
  }
  ROS_INFO_STREAM("world_markers: " << room.obstacles.size() << " disks, " << room.walls.size() << " wall segments, "
                                    << room.polygons.size() << " polygons, " << room.people.size() << " people from " << config.world_file << " in '"
                                    << config.frame_id << "'");
  ros::spin();
  return 0;
}
