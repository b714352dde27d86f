// run_report: scores a run recorded from sim.launch (rosbag) with the offline simulator's
// metrics and writes trajectory.csv + metrics.json in its format (scripts/plot_run.py
// draws the paper's figures from them). Exit 0: safe run; 3: collision or a command
// outside the diamond; 4: the run did not happen (too few steps, no ground truth, no
// motion); 2: bad arguments or unreadable input.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2/utils.h>

#include "amigobot_tracking/TrackingState.h"
#include "amigobot_tracking/VirtualObstacleArray.h"
#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/ros/recorded_run.h"

using namespace amigobot_tracking;

namespace {

const char* kUsage =
    "usage: run_report --bag FILE --world FILE.yaml --out DIR [options]\n"
    "  --name NAME          run name for the plots (default sim)\n"
    "  --tracking-ns NS     namespace of the tracking node's topics (default /tracking)\n"
    "  --cmd-topic T        commands (default /cmd_vel)\n"
    "  --truth-topic T      ground truth, nav_msgs/Odometry in map (default /ground_truth)\n"
    "  --robot-radius R     [m] (0.18)   --offset r [m] (0.3)   --rho-inf [m] (0.1)\n"
    "  --v-max V [m/s] (0.3)   --w-max W [rad/s] (0.8): the diamond of the run\n";

double number(const std::string& flag, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0') {
    std::cerr << "run_report: " << flag << ": '" << text << "' is not a number\n";
    std::exit(2);
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  std::string bag_path, world_path, out, name = "sim", ns = "/tracking", cmd_topic = "/cmd_vel",
                                            truth_topic = "/ground_truth";
  ros_layer::RecordedRunConfig config;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::cerr << "run_report: " << a << " needs a value\n" << kUsage;
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--bag") bag_path = value();
    else if (a == "--world") world_path = value();
    else if (a == "--out") out = value();
    else if (a == "--name") name = value();
    else if (a == "--tracking-ns") ns = value();
    else if (a == "--cmd-topic") cmd_topic = value();
    else if (a == "--truth-topic") truth_topic = value();
    else if (a == "--robot-radius") config.robot_radius = number(a, value());
    else if (a == "--offset") config.offset = number(a, value());
    else if (a == "--rho-inf") config.rho_inf = number(a, value());
    else if (a == "--v-max") config.v_max = number(a, value());
    else if (a == "--w-max") config.w_max = number(a, value());
    else {
      std::cerr << "run_report: unknown option '" << a << "'\n" << kUsage;
      return 2;
    }
  }
  if (bag_path.empty() || world_path.empty() || out.empty()) {
    std::cerr << kUsage;
    return 2;
  }
  try {
    aria::EmulatorOptions world;
    aria::loadWorld(world_path, world);
    config.world = world.obstacles;
    const std::string error = config.validate();
    if (!error.empty()) throw std::invalid_argument("run_report: " + error);

    ros_layer::RecordedRun run(config);
    rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
    const std::string state_topic = ns + "/state", virtual_topic = ns + "/virtual_obstacles";
    rosbag::View view(bag, rosbag::TopicQuery({state_topic, virtual_topic, cmd_topic, truth_topic}));
    for (const rosbag::MessageInstance& msg : view) {
      if (msg.getTopic() == truth_topic) {
        if (auto o = msg.instantiate<nav_msgs::Odometry>()) {
          run.addTruth(o->header.stamp.toSec(), core::Pose2{o->pose.pose.position.x, o->pose.pose.position.y,
                                                            tf2::getYaw(o->pose.pose.orientation)});
        }
      } else if (msg.getTopic() == cmd_topic) {
        if (auto c = msg.instantiate<geometry_msgs::Twist>()) run.addCommand(c->linear.x, c->angular.z);
      } else if (msg.getTopic() == virtual_topic) {
        if (auto a = msg.instantiate<VirtualObstacleArray>()) {
          std::vector<core::Disk> disks;
          for (const auto& o : a->obstacles) {
            core::Disk d;
            d.center = {o.center.x, o.center.y};
            d.radius = o.radius;
            disks.push_back(d);
          }
          run.addVirtualObstacles(std::move(disks));
        }
      } else if (auto s = msg.instantiate<TrackingState>()) {
        run.addState(*s);
      }
    }
    bag.close();
    run.finish();
    const ros_layer::RecordedRunSummary s = run.summary();
    sim::writeTrajectoryCsv(out + "/trajectory.csv", run.rows());
    sim::writeText(out + "/metrics.json", ros_layer::recordedRunJson(s, config, run.allObstacles(), name));
    const sim::RunMetrics& m = s.metrics;
    std::printf("tracking: %llu steps over %.1f s, path %.2f m; |e| < rho in %.1f %% of steps, max |e|/rho %.2f, "
                "AAE %.3f m, ASE %.4f m^2, TEC %.2f\n",
                static_cast<unsigned long long>(m.steps), m.sim_time, s.path_length, 100.0 * s.within_rho_fraction,
                m.max_e_over_rho, m.aae, m.ase, m.tec);
    std::printf("safety: min true body clearance %.3f m to the world, %.3f m to virtual obstacles (%llu at most); "
                "%llu body collisions; %llu of %llu commands outside the diamond (max norm %.3f)\n",
                s.min_clearance_world, s.min_clearance_virtual, static_cast<unsigned long long>(s.virtual_obstacles),
                static_cast<unsigned long long>(m.body_collisions),
                static_cast<unsigned long long>(s.command_violations), static_cast<unsigned long long>(s.commands),
                s.max_command_norm);
    if (!s.ran()) {
      std::fprintf(stderr, "run_report: the run did not happen (%llu enabled steps, %llu ground-truth poses, %.2f m)\n",
                   static_cast<unsigned long long>(m.steps), static_cast<unsigned long long>(s.truth_samples),
                   s.path_length);
      return 4;
    }
    if (s.collided() || s.command_violations > 0) {
      std::fprintf(stderr, "run_report: UNSAFE run: collision or command outside the diamond\n");
      return 3;
    }
  } catch (const std::exception& e) {
    std::cerr << "run_report: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
