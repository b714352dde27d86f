// amigobot_drive: connects to an AmigoBot (or the emulator / a simulator) with the ROS-free
// driver, optionally enables the motors and drives a constant (v, w), printing odometry and
// link figures once a second. A bring-up and smoke-test tool.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "amigobot_tracking/aria/client.h"

using namespace amigobot_tracking::aria;

int main(int argc, char** argv) {
  ClientConfig config;
  config.port = "localhost:8101";
  std::string model = "amigo", params_file, mode = "vel_rvel";
  double v = 0.0, w = 0.0, duration = 5.0;
  bool enable = false;
  CLI::App app("Drives an AmigoBot (or the emulator, or a simulator) at a constant (v, w) with the ROS-free "
               "driver, printing odometry and link figures once a second.",
               "amigobot_drive");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.add_option("--port", config.port, "/dev/ttyUSB0 or host:port")->capture_default_str();
  app.add_option("--baud", config.baud, "serial baud rate")->capture_default_str();
  app.add_option("--model", model, "amigo | amigo-sh (built-in parameters)")->capture_default_str();
  app.add_option("--robot-params", params_file, "robot parameter YAML instead of the built-in set");
  app.add_option("--mode", mode, "motion commands: vel_rvel | vel2")->capture_default_str();
  app.add_flag("--enable", enable, "enable the motors (else the robot only reports)");
  app.add_option("--v", v, "[m/s] forward speed")->capture_default_str();
  app.add_option("--w", w, "[rad/s] turn rate")->capture_default_str();
  app.add_option("--duration", duration, "[s] how long to drive")->capture_default_str();
  try {
    app.parse(argc, argv);
    const auto command_mode = parseCommandMode(mode);
    if (!command_mode) throw CLI::ValidationError("--mode", "expected vel_rvel or vel2, got '" + mode + "'");
    config.command_mode = *command_mode;
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    config.robot = params_file.empty() ? builtinRobotParams(model) : loadRobotParams(params_file);
    config.enable_motors = enable;
    AriaClient client(config);
    client.start();
    const auto start = std::chrono::steady_clock::now();
    for (int tick = 0;; ++tick) {
      client.setVelocity({v, w});
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (tick % 10 == 9 || t >= duration) {
        const ClientStatus s = client.status();
        std::printf("t=%5.1f link=%-10s sips=%llu rate=%4.1f Hz", t, linkStateName(s.link).c_str(),
                    static_cast<unsigned long long>(s.sips), s.sip_rate);
        if (s.robot) {
          const auto& p = s.robot->odometry.pose;
          std::printf(" pose=(%.3f, %.3f, %.3f) motors=%d battery=%.1f V", p.x, p.y, p.theta,
                      s.robot->motors_enabled ? 1 : 0, s.robot->battery_voltage);
        }
        std::printf(" parser errors=%llu\n", static_cast<unsigned long long>(s.parser.errors()));
        std::fflush(stdout);
      }
      if (t >= duration) break;
    }
    client.stop();
  } catch (const std::exception& e) {
    std::cerr << "amigobot_drive: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
