// The driver loaded as the nodelet amigobot_tracking/Driver (found through pluginlib)
// against the amigobot_emulator executable over TCP: motors service and latched state,
// cmd_vel driving, cmd_vel_timeout, odom vs ground truth, tf, sonar (Range and the cloud),
// battery_state, latched stall/bumper/estop, diagnostics, reset_odometry and a clean unload.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <set>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <nodelet/loader.h>
#include <ros/ros.h>
#include <amigobot_tracking/Bumpers.h>
#include <amigobot_tracking/WheelStall.h>
#include <sensor_msgs/BatteryState.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/Range.h>
#include <sensor_msgs/point_cloud2_iterator.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "emulator_process.h"

namespace driver_ros_test {

using namespace amigobot_test;

namespace {

// Sets one double of the driver's dynamic_reconfigure; returns the value now in force, NaN
// when the driver refused the set (the call fails).
double reconfigureDriver(const std::string& name, double value) {
  dynamic_reconfigure::Reconfigure srv;
  dynamic_reconfigure::DoubleParameter p;
  p.name = name;
  p.value = value;
  srv.request.config.doubles.push_back(p);
  if (!ros::service::call("/driver/set_parameters", srv)) return std::nan("");
  for (const auto& d : srv.response.config.doubles) {
    if (d.name == name) return d.value;
  }
  return std::nan("");
}

struct Inbox {
  std::mutex mutex;
  nav_msgs::Odometry odom;
  int odom_count = 0;
  int motors_state = -1;
  double battery = 0.0;
  std::set<std::string> sonar_frames;
  int diagnostics_level = -1;
  std::string diagnostics_message;
  std::string diagnostics_baud;
  sensor_msgs::BatteryState battery_state;
  int battery_states = 0;
  int stalls = 0, bumpers = 0, estops = 0;
  bool estop = true;
  std::size_t bumper_count = 99;
  std::string cloud_frame;
  float cloud_max_x = 0.0f;  // farthest echo ahead [m]
};

// The emulator's world: one disk 1.5 m ahead, in the front sonars' cones.
std::string writeWorld() {
  const std::string path = "/tmp/amigobot_driver_world_" + std::to_string(::getpid()) + ".yaml";
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("obstacles:\n  - {center: [1.5, 0.0], radius: 0.2}\n", f);
  std::fclose(f);
  return path;
}

}  // namespace

TEST(DriverRos, NodeletDrivesTheEmulatorAndReportsEverything) {
  const std::string world = writeWorld();
  EmulatorProcess emu({"--world", world});
  ros::NodeHandle nh;
  ros::param::set("/driver/port", emu.address());
  ros::param::set("/driver/cmd_vel_timeout", 0.6);
  ros::param::set("/driver/trans_accel", 1.0);
  ros::param::set("/driver/trans_decel", 1.0);
  ros::param::set("/driver/link_timeout", 1.5);

  Inbox in;
  auto odom_sub = nh.subscribe<nav_msgs::Odometry>("odom", 10, [&](const nav_msgs::Odometry::ConstPtr& m) {
    std::lock_guard<std::mutex> l(in.mutex);
    in.odom = *m;
    ++in.odom_count;
  });
  auto motors_sub = nh.subscribe<std_msgs::Bool>("motors_state", 10, [&](const std_msgs::Bool::ConstPtr& m) {
    std::lock_guard<std::mutex> l(in.mutex);
    in.motors_state = m->data;
  });
  auto battery_sub = nh.subscribe<std_msgs::Float64>("battery_voltage", 10, [&](const std_msgs::Float64::ConstPtr& m) {
    std::lock_guard<std::mutex> l(in.mutex);
    in.battery = m->data;
  });
  auto sonar_sub = nh.subscribe<sensor_msgs::Range>("sonar_range", 100, [&](const sensor_msgs::Range::ConstPtr& m) {
    std::lock_guard<std::mutex> l(in.mutex);
    in.sonar_frames.insert(m->header.frame_id);
  });
  auto diag_sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
        for (const auto& s : m->status) {
          if (s.name.find("AmigoBot driver") == std::string::npos) continue;
          std::lock_guard<std::mutex> l(in.mutex);
          in.diagnostics_level = s.level;
          in.diagnostics_message = s.message;
          for (const auto& kv : s.values) {
            if (kv.key == "baud") in.diagnostics_baud = kv.value;
          }
        }
      });
  auto battery_state_sub = nh.subscribe<sensor_msgs::BatteryState>(
      "battery", 10, [&](const sensor_msgs::BatteryState::ConstPtr& m) {
        std::lock_guard<std::mutex> l(in.mutex);
        in.battery_state = *m;
        ++in.battery_states;
      });
  auto stall_sub = nh.subscribe<amigobot_tracking::WheelStall>("stall", 10, [&](const amigobot_tracking::WheelStall::ConstPtr& m) {
    std::lock_guard<std::mutex> l(in.mutex);
    in.stalls += !m->left && !m->right;
  });
  auto bumper_sub = nh.subscribe<amigobot_tracking::Bumpers>("bumper", 10, [&](const amigobot_tracking::Bumpers::ConstPtr& m) {
    std::lock_guard<std::mutex> l(in.mutex);
    ++in.bumpers;
    in.bumper_count = m->front.size() + m->rear.size();
  });
  auto estop_sub = nh.subscribe<std_msgs::Bool>("estop", 10, [&](const std_msgs::Bool::ConstPtr& m) {
    std::lock_guard<std::mutex> l(in.mutex);
    ++in.estops;
    in.estop = m->data;
  });
  auto cloud_sub = nh.subscribe<sensor_msgs::PointCloud2>("sonar_cloud", 10, [&](const sensor_msgs::PointCloud2::ConstPtr& m) {
    std::lock_guard<std::mutex> l(in.mutex);
    in.cloud_frame = m->header.frame_id;
    for (sensor_msgs::PointCloud2ConstIterator<float> x(*m, "x"); x != x.end(); ++x) in.cloud_max_x = std::max(in.cloud_max_x, *x);
  });
  ros::Publisher cmd_pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  tf2_ros::Buffer tf_buffer;
  tf2_ros::TransformListener tf_listener(tf_buffer);

  nodelet::Loader loader(false);
  ASSERT_TRUE(loader.load("/driver", "amigobot_tracking/Driver", {}, {}));
  auto locked = [&](auto f) {
    std::lock_guard<std::mutex> l(in.mutex);
    return f();
  };
  ASSERT_TRUE(waitFor([&] { return locked([&] { return in.odom_count > 3; }); }, 30.0)) << "no odom";
  EXPECT_TRUE(waitFor([&] { return locked([&] { return in.motors_state == 0; }); }, 5.0)) << "motors_state not latched";
  std_srvs::Empty empty;
  ASSERT_TRUE(ros::service::call("enable_motors", empty));
  EXPECT_TRUE(waitFor([&] { return locked([&] { return in.motors_state == 1; }); }, 5.0));
  EXPECT_TRUE(emu.truth().motors);

  geometry_msgs::Twist cmd;
  cmd.linear.x = 0.2;
  bool moved = false;
  for (int i = 0; i < 25; ++i) {  // 2.5 s of cmd_vel at 10 Hz
    cmd_pub.publish(cmd);
    ros::Duration(0.1).sleep();
    moved = moved || emu.truth().v > 0.15;
  }
  EXPECT_TRUE(moved) << "the robot did not follow cmd_vel";
  // cmd_vel stops: after cmd_vel_timeout the driver stops the robot.
  EXPECT_TRUE(waitFor([&] { return std::abs(emu.truth().v) < 1e-6; }, 5.0));
  ros::Duration(0.3).sleep();
  const Truth truth = emu.truth();
  const nav_msgs::Odometry odom = locked([&] { return in.odom; });
  EXPECT_GT(truth.pose.x, 0.3);
  EXPECT_NEAR(odom.pose.pose.position.x, truth.pose.x, 0.01);
  EXPECT_NEAR(odom.pose.pose.position.y, truth.pose.y, 0.01);
  EXPECT_EQ(odom.header.frame_id, "odom");
  EXPECT_EQ(odom.child_frame_id, "base_link");
  EXPECT_GT(odom.pose.covariance[0], 0.0);

  EXPECT_TRUE(tf_buffer.canTransform("odom", "base_link", ros::Time(0), ros::Duration(2.0)));
  EXPECT_TRUE(tf_buffer.canTransform("base_link", "sonar_7", ros::Time(0), ros::Duration(2.0)));
  EXPECT_TRUE(waitFor([&] { return locked([&] { return in.sonar_frames.size() == 8; }); }, 5.0));
  EXPECT_NEAR(locked([&] { return in.battery; }), 12.6, 0.05);
  // The disk 1.5 m from the start (its surface 1.3 m), seen from wherever the robot stopped.
  EXPECT_TRUE(waitFor([&] { return locked([&] { return in.cloud_max_x > 1.0f; }); }, 5.0));
  EXPECT_LT(locked([&] { return in.cloud_max_x; }), 1.35f);
  EXPECT_EQ(locked([&] { return in.cloud_frame; }), "base_link");
  // AmigOS reports voltage only: no state of charge, no charge state.
  EXPECT_TRUE(waitFor([&] { return locked([&] { return in.battery_states > 0; }); }, 5.0));
  const sensor_msgs::BatteryState battery = locked([&] { return in.battery_state; });
  EXPECT_NEAR(battery.voltage, 12.6, 0.05);
  EXPECT_TRUE(std::isnan(battery.percentage));
  EXPECT_EQ(battery.power_supply_status, sensor_msgs::BatteryState::POWER_SUPPLY_STATUS_UNKNOWN);
  // Latched and sent on change only: one message each while nothing changes.
  EXPECT_EQ(locked([&] { return in.stalls; }), 1);
  EXPECT_EQ(locked([&] { return in.estops; }), 1);
  EXPECT_FALSE(locked([&] { return in.estop; }));
  EXPECT_EQ(locked([&] { return in.bumpers; }), 1);
  EXPECT_EQ(locked([&] { return in.bumper_count; }), 0u);  // the emulator announces no bumpers
  EXPECT_EQ(locked([&] { return in.diagnostics_baud; }), "- (TCP)");
  EXPECT_TRUE(waitFor([&] { return locked([&] { return in.diagnostics_level == 0; }); }, 5.0))
      << locked([&] { return in.diagnostics_message; });

  ASSERT_TRUE(ros::service::call("reset_odometry", empty));
  EXPECT_TRUE(waitFor([&] { return locked([&] { return std::abs(in.odom.pose.pose.position.x) < 1e-3; }); }, 5.0));

  // A NaN cmd_vel is refused: the robot stays put.
  cmd.linear.x = std::nan("");
  cmd_pub.publish(cmd);
  ros::Duration(0.5).sleep();
  EXPECT_LT(std::abs(emu.truth().v), 1e-6);

  // dynamic_reconfigure: a smaller diamond holds at once; one beyond the robot is refused.
  EXPECT_DOUBLE_EQ(reconfigureDriver("v_max", 0.1), 0.1);
  // Above the robot's max_velocity 1.0: the call fails and the limit in force stays.
  EXPECT_TRUE(std::isnan(reconfigureDriver("v_max", 1.5))) << "a refused set must fail the reconfigure call";
  double in_force = 0.0;
  EXPECT_TRUE(ros::param::get("/driver/v_max", in_force));
  EXPECT_DOUBLE_EQ(in_force, 0.1);
  cmd.linear.x = 0.3;
  double fastest = 0.0;
  for (int i = 0; i < 20; ++i) {
    cmd_pub.publish(cmd);
    ros::Duration(0.1).sleep();
    fastest = std::max(fastest, emu.truth().v);
  }
  EXPECT_GT(fastest, 0.05);
  EXPECT_LT(fastest, 0.1 + 1e-3);

  ASSERT_TRUE(loader.unload("/driver"));
  EXPECT_TRUE(waitFor([&] { const Truth t = emu.truth(); return !t.open && !t.motors; }, 5.0))
      << "unload must disable the motors and close the robot";
  std::remove(world.c_str());
}

TEST(DriverRos, BadParameterKeepsTheManagerAliveAndSaysWhich) {
  ros::param::set("/bad_driver/command_mode", "vel3");
  nodelet::Loader loader(false);
  // The nodelet loads (the manager survives) but does not start a driver.
  EXPECT_TRUE(loader.load("/bad_driver", "amigobot_tracking/Driver", {}, {}));
  ros::Duration(0.5).sleep();
  EXPECT_FALSE(ros::service::exists("/enable_motors", false));
  EXPECT_TRUE(loader.unload("/bad_driver"));
}

}  // namespace driver_ros_test
