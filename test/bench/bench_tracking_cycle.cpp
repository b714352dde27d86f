// Google Benchmark: one whole control cycle of the tracking node (TrackingNode::controlCycle:
// tf2 lookups of robot and target, a new 720-beam scan -> disks, plus 3 virtual obstacles,
// controller step, cmd_vel and ~state publish, markers when subscribed). Printed, never
// asserted. Target: <= 0.5 ms. Needs a ROS master (`make bench` starts a private one).
//
// Nothing spins the callback queue: the node's timer never fires, only the benchmark calls
// the cycle. The tf2 buffer is shared and fed here (map -> odom -> base_link, base_link ->
// laser static, map -> target), three setTransform calls per cycle included in the time.
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <memory>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include "amigobot_tracking/TrackingState.h"
#include "amigobot_tracking/ros/conversions.h"
#include "amigobot_tracking/ros/tracking_node.h"

using amigobot_tracking::ros_layer::toTransform;
using amigobot_tracking::ros_layer::TrackingNode;

namespace {

// A 720-beam scan of a 6 x 4 m room seen from its centre.
sensor_msgs::LaserScan::Ptr roomScan() {
  auto scan = boost::make_shared<sensor_msgs::LaserScan>();
  scan->header.frame_id = "laser";
  scan->angle_min = -M_PI;
  scan->angle_increment = 2.0 * M_PI / 720;
  scan->angle_max = scan->angle_min + 719 * scan->angle_increment;
  scan->range_min = 0.05f;
  scan->range_max = 8.0f;
  for (int i = 0; i < 720; ++i) {
    const double a = scan->angle_min + i * scan->angle_increment, c = std::cos(a), s = std::sin(a);
    double r = std::numeric_limits<double>::infinity();
    if (std::abs(c) > 1e-9) r = std::min(r, 3.0 / std::abs(c));
    if (std::abs(s) > 1e-9) r = std::min(r, 2.0 / std::abs(s));
    scan->ranges.push_back(static_cast<float>(r));
  }
  return scan;
}

template <class M>
void ignore(const boost::shared_ptr<M const>&) {}

void BM_ControlCycle(benchmark::State& state) {
  const bool subscribed = state.range(0) != 0;
  ros::NodeHandle nh("bench"), pnh("bench/tracking");
  pnh.setParam("autostart", true);
  pnh.setParam("pose_timeout", 10.0);
  pnh.setParam("scan_timeout", 10.0);
  XmlRpc::XmlRpcValue obstacles;
  for (int i = 0; i < 3; ++i) {
    obstacles[i]["id"] = "v" + std::to_string(i);
    obstacles[i]["center"][0] = -1.0 + i;
    obstacles[i]["center"][1] = 1.2;
    obstacles[i]["radius"] = 0.2;
  }
  pnh.setParam("virtual_obstacles", obstacles);
  auto buffer = std::make_shared<tf2_ros::Buffer>();
  auto node = std::make_unique<TrackingNode>(nh, pnh, buffer);
  if (!node->start()) {
    state.SkipWithError("tracking node did not start");
    return;
  }
  ros::Subscriber cmd_sub, state_sub, marker_sub;
  if (subscribed) {  // in-process subscribers: state and markers are built and serialised
    cmd_sub = nh.subscribe("cmd_vel", 1, &ignore<geometry_msgs::Twist>);
    state_sub = pnh.subscribe("state", 1, &ignore<amigobot_tracking::TrackingState>);
    marker_sub = pnh.subscribe("markers", 1, &ignore<visualization_msgs::MarkerArray>);
  }
  buffer->setTransform(toTransform("base_link", "laser", {0.1, 0.0, 0.0}, ros::Time(0)), "bench", true);
  sensor_msgs::LaserScan::Ptr scans[2] = {roomScan(), roomScan()};  // alternate: every cycle sees a new scan
  double t = 0.0;
  int k = 0;
  for (auto _ : state) {
    const ros::Time now = ros::Time::now();
    t += 0.05;
    buffer->setTransform(toTransform("map", "odom", {0.0, 0.0, 0.0}, now), "bench");
    const amigobot_tracking::core::Pose2 robot{0.5 * std::cos(0.1 * t), 0.5 * std::sin(0.1 * t), 0.1 * t + M_PI / 2};
    const amigobot_tracking::core::Pose2 target{std::cos(0.1 * t + 0.5), std::sin(0.1 * t + 0.5), 0.0};
    buffer->setTransform(toTransform("odom", "base_link", robot, now), "bench");
    buffer->setTransform(toTransform("map", "target", target, now), "bench");
    sensor_msgs::LaserScan::Ptr& scan = scans[k++ % 2];
    scan->header.stamp = now;
    node->onScan(scan);
    node->controlCycle(now);
  }
  if (node->status() != "tracking") state.SkipWithError(("not tracking: " + node->status()).c_str());
  const amigobot_tracking::ros_layer::CycleStats stats = node->cycleStats();
  state.counters["node_mean_us"] = stats.cycles ? stats.sum_us / stats.cycles : 0.0;
  state.counters["node_max_us"] = stats.max_us;
  pnh.deleteParam("");
}
BENCHMARK(BM_ControlCycle)->Arg(0)->Arg(1)->ArgName("subscribed")->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "bench_tracking_cycle", ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
  if (!ros::master::check()) {
    fprintf(stderr, "bench_tracking_cycle: no ROS master at %s (make bench starts one)\n", ros::master::getURI().c_str());
    return 1;
  }
  // Each benchmark run builds a node, which logs its parameters at INFO (~1000 lines over the
  // repetitions); the figures are what `make bench` is for.
  if (ros::console::set_logger_level(ROSCONSOLE_DEFAULT_NAME, ros::console::levels::Warn)) {
    ros::console::notifyLoggerLevelsChanged();
  }
  ros::start();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  ros::shutdown();
  return 0;
}
