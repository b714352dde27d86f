// run_report: scores a run recorded from sim.launch (rosbag) with the offline simulator's
// metrics and writes trajectory.csv + metrics.json in its format (scripts/reports/plot_run.py
// draws the paper's figures from them) and judges tracking (sim/tracking_verdict.h). Exit 0:
// safe run that tracked; 3: collision or a command outside the diamond; 4: the run did not
// happen (too few steps, no ground truth, no motion); 5: safe, but it did not track (true
// error above rho_inf + tolerance outside obstacle episodes and their recovery time, or at
// the end); 2: bad arguments or unreadable input (also: a world with people and a bag
// without the emulator's clock, TRUTH_TOPIC_clock, to place them).
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/TimeReference.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <nlohmann/json.hpp>
#include <tf2/utils.h>
#include <tf2_msgs/TFMessage.h>

#include "amigobot_tracking/TrackingState.h"
#include "amigobot_tracking/VirtualObstacleArray.h"
#include "amigobot_tracking/ros/emulator_clock.h"
#include "amigobot_tracking/ros/localization_error.h"
#include "amigobot_tracking/ros/recorded_run.h"
#include "amigobot_tracking/world/world.h"

using namespace amigobot_tracking;

int main(int argc, char** argv) {
  std::string bag_path, world_path, out, name = "sim", ns = "/tracking", cmd_topic = "/cmd_vel",
                                            truth_topic = "/ground_truth";
  ros_layer::RecordedRunConfig config;
  CLI::App app("Scores a run recorded from sim.launch (rosbag) with the offline simulator's metrics; writes "
               "trajectory.csv and metrics.json (scripts/reports/plot_run.py draws them).",
               "run_report");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.add_option("--bag", bag_path, "the recorded run")->required();
  app.add_option("--world", world_path, "world YAML of the run (world/world.h)")->required();
  app.add_option("--out", out, "folder for trajectory.csv and metrics.json")->required();
  app.add_option("--name", name, "run name for the plots")->capture_default_str();
  app.add_option("--tracking-ns", ns, "namespace of the tracking node's topics")->capture_default_str();
  app.add_option("--cmd-topic", cmd_topic, "commands (geometry_msgs/Twist)")->capture_default_str();
  app.add_option("--truth-topic", truth_topic, "ground truth, nav_msgs/Odometry in map")->capture_default_str();
  app.add_option("--robot-radius", config.robot_radius, "[m] R")->capture_default_str();
  app.add_option("--offset", config.offset, "[m] r, offset of the controlled point")->capture_default_str();
  app.add_option("--rho-inf", config.rho_inf, "[m] the law's rho_inf (plots, tracking bound)")->capture_default_str();
  app.add_option("--law", config.law, "a robot law of core/law_registry (paper | fixed_rho | recommended) or its alias escape (paper + tangential_avoidance), recorded in metrics.json")
      ->capture_default_str();
  app.add_option("--body-safe", config.body_safe, "the run's body_safe (effective radius R + r)")->capture_default_str();
  app.add_option("--delta", config.verdict.band, "[m] detection band: obstacle episode while a clearance < delta")
      ->capture_default_str();
  app.add_option("--tolerance", config.verdict.tolerance,
                 "[m] tracking bound is rho_inf + this (localisation error, sampling skew)")
      ->capture_default_str();
  app.add_option("--recovery-time", config.verdict.recovery_time,
                 "[s] not judged after the start and after each obstacle episode")
      ->capture_default_str();
  app.add_option("--v-max", config.v_max, "[m/s] the run's diamond")->capture_default_str();
  app.add_option("--w-max", config.w_max, "[rad/s] the run's diamond")->capture_default_str();
  std::string global_frame = "map", base_frame = "base_link";
  double localization_skip = 2.0;
  app.add_option("--global-frame", global_frame, "localisation error: the believed pose is tf global -> base")
      ->capture_default_str();
  app.add_option("--base-frame", base_frame, "localisation error: the robot's frame (the truth's child)")
      ->capture_default_str();
  app.add_option("--localization-skip", localization_skip, "[s] localisation error: start-up not scored")
      ->capture_default_str();
  app.footer("Exit 0: safe run that tracked; 3: collision or a command outside the diamond; 4: the run did not "
             "happen; 5: safe but did not track (true |e| > rho_inf + tolerance outside obstacle episodes and their "
             "recovery time, or at the end); 2: bad arguments or unreadable input.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    config.verdict.rho_inf = config.rho_inf;
    config.world = world::loadWorld(world_path);
    const std::string error = config.validate();
    if (!error.empty()) throw std::invalid_argument("run_report: " + error);

    ros_layer::RecordedRun run(config);
    rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
    const std::string state_topic = ns + "/state", virtual_topic = ns + "/virtual_obstacles";
    ros_layer::LocalizationErrorMeter localization(global_frame, base_frame, localization_skip);
    // The world's people move on the emulator's clock: ground_truth_localization's pairs place them.
    const std::string clock_topic = truth_topic + "_clock";
    ros_layer::EmulatorClock clock;
    std::uint64_t truth_without_clock = 0;
    rosbag::View view(bag, rosbag::TopicQuery({state_topic, virtual_topic, cmd_topic, truth_topic, clock_topic, "/tf",
                                               "/tf_static"}));
    for (const rosbag::MessageInstance& msg : view) {
      if (msg.getTopic() == clock_topic) {
        if (auto c = msg.instantiate<sensor_msgs::TimeReference>()) clock.add(c->header.stamp.toSec(), c->time_ref.toSec());
      } else if (msg.getTopic() == "/tf" || msg.getTopic() == "/tf_static") {
        if (auto t = msg.instantiate<tf2_msgs::TFMessage>()) localization.addTf(*t, msg.getTopic() == "/tf_static");
      } else if (msg.getTopic() == truth_topic) {
        if (auto o = msg.instantiate<nav_msgs::Odometry>()) {
          const core::Pose2 truth{o->pose.pose.position.x, o->pose.pose.position.y,
                                  tf2::getYaw(o->pose.pose.orientation)};
          if (!config.world.people.empty() && !clock.known()) {  // where the people are is unknown yet
            ++truth_without_clock;
            continue;
          }
          run.addTruth(o->header.stamp.toSec(), truth, clock.at(o->header.stamp.toSec()));
          localization.addTruth(o->header.stamp, truth);
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
    if (!config.world.people.empty() && !clock.known()) {
      throw std::runtime_error("the world has " + std::to_string(config.world.people.size()) + " people but " + bag_path +
                               " has no " + clock_topic + " (sensor_msgs/TimeReference) to place them: record it");
    }
    if (truth_without_clock > 0) {
      std::printf("note: %llu ground-truth poses before the first %s were not scored (people unplaced)\n",
                  static_cast<unsigned long long>(truth_without_clock), clock_topic.c_str());
    }
    run.finish();
    const ros_layer::RecordedRunSummary s = run.summary();
    sim::writeTrajectoryCsv(out + "/trajectory.csv", run.rows());
    const ros_layer::LocalizationErrorStats loc = localization.finish();
    nlohmann::json metrics = nlohmann::json::parse(ros_layer::recordedRunJson(s, config, run.allObstacles(), name));
    metrics["localization"] = {{"frames", global_frame + " -> " + base_frame},
                               {"samples", loc.samples},
                               {"missed", loc.missed},
                               {"rms_position_m", loc.rms_position},
                               {"max_position_m", loc.max_position},
                               {"rms_heading_deg", loc.rms_heading * 180.0 / M_PI},
                               {"max_heading_deg", loc.max_heading * 180.0 / M_PI}};
    sim::writeText(out + "/metrics.json", metrics.dump(2) + "\n");
    const sim::RunMetrics& m = s.metrics;
    std::printf("law: %s\n", config.law.c_str());
    std::printf("tracking: %llu steps over %.1f s, path %.2f m; |e| < rho in %.1f %% of steps, max |e|/rho %.2f, "
                "AAE %.3f m, ASE %.4f m^2, IAE %.2f m s, ISE %.3f m^2 s, TEC %.2f; %.0f %% of steps saturated\n",
                static_cast<unsigned long long>(m.steps), m.sim_time, s.path_length, 100.0 * s.within_rho_fraction,
                m.max_e_over_rho, m.aae, m.ase, m.iae, m.ise, m.tec,
                m.steps > 0 ? 100.0 * static_cast<double>(m.saturated_steps) / m.steps : 0.0);
    const sim::TrackingVerdict& v = s.tracking;
    std::printf("true error: AAE %.3f m, max %.3f m, final %.3f m; %zu obstacle episode(s)", m.true_aae,
                m.max_true_error, v.final_error, v.episodes.size());
    for (const sim::ObstacleEpisode& e : v.episodes) {
      std::printf(" [%.1f-%.1f s, peak %.2f m, ", e.start, e.end, e.peak_error);
      if (e.recovered_after < 0.0) {
        std::printf("never back under %.2f m]", v.bound);
      } else {
        std::printf("back under %.2f m after %.1f s]", v.bound, e.recovered_after);
      }
    }
    std::printf("\ntracking verdict: %s (judged %.0f %% of the run: max true |e| %.3f m against rho_inf + tolerance "
                "%.3f m, %.0f s after the start and each episode)%s%s\n",
                v.tracked ? "TRACKED" : "DID NOT TRACK", 100.0 * v.judged_fraction, v.max_judged_error, v.bound,
                config.verdict.recovery_time, v.reason.empty() ? "" : ": ", v.reason.c_str());
    std::printf("safety: min true body clearance %.3f m to the world (%.3f m to its %zu people), %.3f m to virtual "
                "obstacles (%llu at most); %llu body collisions; %llu of %llu commands outside the diamond (max norm "
                "%.3f)\n",
                s.min_clearance_world, s.min_clearance_people, config.world.people.size(), s.min_clearance_virtual,
                static_cast<unsigned long long>(s.virtual_obstacles),
                static_cast<unsigned long long>(m.body_collisions),
                static_cast<unsigned long long>(s.command_violations), static_cast<unsigned long long>(s.commands),
                s.max_command_norm);
    std::printf("localisation: tf %s -> %s against the ground truth at %llu samples (%llu without a pose): "
                "RMS %.3f m, max %.3f m; heading RMS %.2f deg, max %.2f deg\n",
                global_frame.c_str(), base_frame.c_str(), static_cast<unsigned long long>(loc.samples),
                static_cast<unsigned long long>(loc.missed), loc.rms_position, loc.max_position,
                loc.rms_heading * 180.0 / M_PI, loc.max_heading * 180.0 / M_PI);
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
    if (!v.tracked) {
      std::fprintf(stderr, "run_report: the run did not track: %s\n", v.reason.c_str());
      return 5;
    }
  } catch (const std::exception& e) {
    std::cerr << "run_report: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
