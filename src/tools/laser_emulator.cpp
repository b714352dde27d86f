// laser_emulator: a ROS-free laser stand-in, the sensor-side twin of amigobot_emulator. It
// speaks a real laser's protocol (SCIP 2.0 over TCP and a pseudo-terminal for hokuyo_urg,
// CoLa-A over TCP for sick_tim5xx and sick_lms1xx, Slamtec's binary protocol over a
// pseudo-terminal for rplidar) and serves ray-cast scans of a world file from the robot's
// true pose, read from amigobot_emulator's status socket.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "amigobot_tracking/aria/emulator_status.h"
#include "amigobot_tracking/core/support/program_arguments.h"
#include "amigobot_tracking/link/emulator_link.h"
#include "amigobot_tracking/sensors/laser_emulator_server.h"
#include "amigobot_tracking/sensors/laser_registry.h"
#include "amigobot_tracking/world/world.h"

using namespace amigobot_tracking;

namespace {

// Live faults for the e2e tests (lock-free atomics: safe in a signal handler).
std::atomic<bool> g_blind{false}, g_halve{false};
void onToggle(int signal) {
  std::atomic<bool>& fault = signal == SIGUSR1 ? g_blind : g_halve;
  fault.store(!fault.load());
}

}  // namespace

int main(int argc, char** argv) {
  std::string model_name = "hokuyo_urg", world_file, status_host = "127.0.0.1", fault = "none";
  int status_port = -1, endpoint = 0;
  double scan_frequency = 0.0, scan_resolution = 0.0;  // read only when given: the model's own otherwise
  std::vector<double> pose{0.0, 0.0, 0.0};
  sensors::ScanSourceOptions scan;
  sensors::LaserServerOptions server;
  CLI::App app("A ROS-free laser stand-in: SCIP 2.0 (Hokuyo URG-04LX), CoLa-A (SICK TiM5xx, LMS1xx) or RPLIDAR "
               "(Slamtec A1) scans of a world file.",
               "laser_emulator");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.add_option("--model", model_name, sensors::laserModelList())->capture_default_str();
  CLI::Option* frequency_option = app.add_option("--scan-frequency", scan_frequency,
                                                 "[Hz] models with a scan to choose (" + sensors::scanSettingChoices() + ")");
  CLI::Option* resolution_option =
      app.add_option("--resolution", scan_resolution, "[deg] angular resolution, as --scan-frequency");
  CLI::Option* endpoint_option = app.add_option(
      "--endpoint", endpoint,
      "serve the model's own link from PORT, where the driver's port laser_emulator:PORT finds it: TCP on PORT, "
      "or a serial-only model's pty at /tmp/amigobot_laser_MODEL_PORT (instead of --tcp-port / --pty)");
  CLI::Option* tcp_option =
      app.add_option("--tcp-port", server.tcp_port, "TCP port (0 = any free port; -1 = none)")->capture_default_str();
  app.add_option("--bind", server.bind_address, "IPv4 address to listen on")->capture_default_str();
  CLI::Option* pty_option = app.add_option(
      "--pty", server.pty_link, "models with a serial port: also serve a pseudo-terminal, symlinked at this path");
  endpoint_option->excludes(tcp_option)->excludes(pty_option);
  app.add_option("--world", world_file, "world YAML (world/world.h): the disks, walls and polygons the laser sees");
  app.add_option("--status-port", status_port, "amigobot_emulator's status port: the robot's true pose (-1: --pose)")
      ->capture_default_str();
  app.add_option("--status-host", status_host, "host of the status socket")->capture_default_str();
  app.add_option("--pose", pose, "fixed robot pose x y theta [m m rad] without a status socket")->expected(3);
  app.add_option("--mount-x", scan.mount.x, "laser in base_link [m]")->capture_default_str();
  app.add_option("--mount-y", scan.mount.y, "laser in base_link [m]")->capture_default_str();
  app.add_option("--mount-yaw", scan.mount.theta, "laser in base_link [rad]")->capture_default_str();
  app.add_flag("--upside-down", scan.upside_down, "laser mounted upside down (beams sweep clockwise)");
  app.add_option("--range-noise", scan.range_noise, "std-dev of the range noise [m]")->capture_default_str();
  app.add_option("--dropout", scan.dropout, "probability of a beam without measurement")->capture_default_str();
  app.add_option("--seed", scan.seed, "noise seed")->capture_default_str();
  app.add_option("--fault", fault, "none | malformed | truncated | checksum | stall | disconnect")->capture_default_str();
  app.add_option("--fault-every", server.fault_every, "apply the fault to every n-th streamed scan")->capture_default_str();
  app.add_option("--stall-time", server.stall_time, "silence of one stall [s]")->capture_default_str();
  app.footer("Prints 'READY tcp=PORT pty=PATH' on stdout once it listens. Live faults: SIGUSR1 switches a blind "
             "laser on or off (every beam reports no return), SIGUSR2 half the scan rate (every other scan "
             "not sent).");
  try {
    app.parse(core::ownArguments(argc, argv));
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    server.fault = sensors::parseFault(fault);
    // The registry's entry decides (scan setting, link): this tool names no model.
    const sensors::LaserModel model = sensors::emulatedLaserModel(
        model_name, frequency_option->count() ? std::optional<double>(scan_frequency) : std::nullopt,
        resolution_option->count() ? std::optional<double>(scan_resolution) : std::nullopt);
    if (endpoint_option->count()) {
      const sensors::LaserEndpoint link = sensors::laserEmulatorEndpoint(model_name, endpoint);
      server.tcp_port = link.tcp_port;
      server.pty_link = link.pty;
    }
    world::World room;
    if (!world_file.empty()) room = world::loadWorld(world_file);
    const core::Pose2 fixed{pose[0], pose[1], pose[2]};
    std::unique_ptr<aria::StatusClient> status;
    if (status_port > 0) status = std::make_unique<aria::StatusClient>(status_host, status_port, 0.05, 0.5);
    const auto start = std::chrono::steady_clock::now();
    sensors::PoseSource source = [&](core::Pose2* base, double* t) {
      if (!status) {
        *base = fixed;
        *t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return true;
      }
      aria::EmulatorStatus robot;
      if (!status->query(&robot).empty()) return false;  // no truth, no scan (a reconnect follows)
      *base = robot.pose;
      *t = robot.t;
      return true;
    };
    sensors::LaserEmulatorServer io(model, sensors::ScanSource(model, room, scan), source, server);
    io.open();
    const std::atomic<bool>& stop = link::stopOnSignals();
    io.setLiveFaults(&g_blind, &g_halve);
    std::signal(SIGUSR1, onToggle);
    std::signal(SIGUSR2, onToggle);
    std::printf("READY tcp=%d pty=%s\n", io.tcpPort(), io.ptyName().empty() ? "-" : io.ptyName().c_str());
    std::fflush(stdout);
    io.run(stop);
  } catch (const std::exception& e) {
    std::cerr << "laser_emulator: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
