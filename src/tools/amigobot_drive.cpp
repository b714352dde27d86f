// amigobot_drive: connects to an AmigoBot (or the emulator / a simulator) with the ROS-free
// driver, optionally enables the motors and drives a constant (v, w), printing odometry and
// link figures once a second. A bring-up and smoke-test tool.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>

#include "amigobot_tracking/aria/client.h"

using namespace amigobot_tracking::aria;

int main(int argc, char** argv) {
  ClientConfig config;
  config.port = "localhost:8101";
  std::string model = "amigo", params_file;
  double v = 0.0, w = 0.0, duration = 5.0;
  bool enable = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "amigobot_drive: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    try {
      if (a == "--port") config.port = value();
      else if (a == "--baud") config.baud = std::stoi(value());
      else if (a == "--model") model = value();
      else if (a == "--robot-params") params_file = value();
      else if (a == "--mode") {
        const auto mode = parseCommandMode(value());
        if (!mode) throw std::invalid_argument("--mode: expected vel_rvel or vel2");
        config.command_mode = *mode;
      } else if (a == "--v") v = std::stod(value());
      else if (a == "--w") w = std::stod(value());
      else if (a == "--duration") duration = std::stod(value());
      else if (a == "--enable") enable = true;
      else {
        std::cerr << "usage: amigobot_drive [--port /dev/ttyUSB0|host:port] [--baud N] [--model amigo|amigo-sh]\n"
                     "       [--robot-params FILE] [--mode vel_rvel|vel2] [--enable] [--v M/S] [--w RAD/S]\n"
                     "       [--duration S]\n";
        return a == "-h" || a == "--help" ? 0 : 2;
      }
    } catch (const std::exception& e) {
      std::cerr << "amigobot_drive: " << a << ": " << e.what() << "\n";
      return 2;
    }
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
