// sim_laser: a planar laser for the emulated robot. Ray casts the emulator's world (the
// same world YAML as amigobot_emulator --world) from the pose of laser_frame in
// global_frame (tf) and publishes `scan` stamped with that pose's time. The world's people
// stand where they are on the emulator's clock at that time (ground_truth_clock).
// Parameters (private): include/amigobot_tracking/ros/sim_laser.h (SimLaserConfig).
#include <random>

#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <sensor_msgs/TimeReference.h>

#include "amigobot_tracking/ros/conversions.h"
#include "amigobot_tracking/ros/emulator_clock.h"
#include "amigobot_tracking/ros/sim_laser.h"
#include "amigobot_tracking/world/world.h"
#include "amigobot_tracking/ros/master_watch.h"
#include "amigobot_tracking/ros/node_command_line.h"

using namespace amigobot_tracking;

const ros_layer::NodeHelp kHelp{
    "A planar laser for the emulated robot: ray casts the world file from the pose of "
    "laser_frame and publishes `scan`.",
    "include/amigobot_tracking/ros/sim_laser.h (SimLaserConfig)."};

int main(int argc, char** argv) {
  ros_layer::initNode(argc, argv, "sim_laser", kHelp);
  ros::NodeHandle nh, pnh("~");
  // A restarted master learns this node's topics again, as the nodelets' (ros/master_watch.h).
  const auto master_watch = ros_layer::MasterWatch::shared();
  ros_layer::SimLaserConfig config;
  if (!ros_layer::configLoaded("sim_laser", ros_layer::loadSimLaserConfig(pnh, &config))) return 1;
  world::World room;
  try {
    room = world::loadWorld(config.world_file);
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("sim_laser: " << e.what());
    return 1;
  }
  ROS_INFO_STREAM("sim_laser: " << room.obstacles.size() << " disks, " << room.walls.size() << " wall segments, "
                                << room.polygons.size() << " polygons from " << config.world_file << ", "
                                << config.beams << " beams in '" << config.laser_frame << "' at " << config.rate
                                << " Hz");

  tf2_ros::Buffer tf;
  tf2_ros::TransformListener listener(tf);
  ros::Publisher pub = nh.advertise<sensor_msgs::LaserScan>("scan", 5);
  // People move on the emulator's clock (world/world.h): its pairs with ROS time place them.
  ros_layer::EmulatorClock clock;
  ros::Subscriber clock_sub;
  if (!room.people.empty()) {
    clock_sub = nh.subscribe<sensor_msgs::TimeReference>("ground_truth_clock", 5, [&](const sensor_msgs::TimeReference::ConstPtr& c) {
      clock.add(c->header.stamp.toSec(), c->time_ref.toSec());
    });
  }
  std::mt19937 rng(static_cast<std::uint32_t>(config.seed));
  ros::Time last_stamp;
  ros::Rate rate(config.rate);
  while (ros::ok()) {
    rate.sleep();
    ros::spinOnce();
    geometry_msgs::TransformStamped pose;
    try {
      pose = tf.lookupTransform(config.global_frame, config.laser_frame, ros::Time(0));
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "sim_laser: no pose of '%s' in '%s' yet: %s", config.laser_frame.c_str(),
                        config.global_frame.c_str(), e.what());
      continue;
    }
    if (pose.header.stamp == last_stamp) continue;  // no new pose: no new scan (tf stalled)
    last_stamp = pose.header.stamp;
    const world::World now = room.people.empty() ? room : world::worldAt(room, clock.at(pose.header.stamp.toSec()));
    sensor_msgs::LaserScan scan = ros_layer::simulateScan(ros_layer::toPose2(pose.transform), now, config, &rng);
    scan.header.stamp = pose.header.stamp;
    pub.publish(scan);
  }
  return 0;
}
