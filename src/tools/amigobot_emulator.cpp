// amigobot_emulator: a ROS-free AmigoBot stand-in that speaks the robot's protocol over
// TCP and a pseudo-terminal and reports its ground-truth pose on a status socket.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/aria/emulator_server.h"
#include "amigobot_tracking/core/support/program_arguments.h"
#include "amigobot_tracking/link/emulator_link.h"
#include "amigobot_tracking/world/world.h"

using namespace amigobot_tracking::aria;

namespace {

// --exit-report: the emulator's last word for whoever started it without reading its stderr
// (roslaunch's output="log" in the end-to-end tests): "running pid N" while it serves, then
// "exit CODE: why". An unwritable file is not an error: the report is a courtesy.
void report(const std::string& path, const std::string& line) {
  if (path.empty()) return;
  std::ofstream out(path, std::ios::trunc);
  out << line << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  EmulatorOptions robot;
  EmulatorServerOptions server;
  std::string model = "amigo", params_file, world_file, name, command_log, exit_report;
  std::uint32_t seed = robot.seed;
  int control_port = -1;
  CLI::App app("A ROS-free AmigoBot stand-in: the robot's protocol over TCP and a pseudo-terminal, its "
               "ground truth on a status socket.",
               "amigobot_emulator");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // a repeated option: the last wins
  app.add_option("--tcp-port", server.tcp_port, "robot port over TCP (0 = any free port; -1 = none)")
      ->capture_default_str();
  app.add_option("--bind", server.bind_address, "IPv4 address to listen on")->capture_default_str();
  app.add_option("--pty", server.pty_link, "also serve a pseudo-terminal, symlinked at this path");
  app.add_option("--status-port", server.status_port,
                 "ground-truth status socket (0 = any free port; -1 = none): send any line, get "
                 "'t x y theta v w motors open watchdog'")
      ->capture_default_str();
  app.add_option("--control-port", control_port,
                 "fault injection (0 = any free port; -1 = none): a line 'teleport x y theta' moves the true pose "
                 "there, the odometry carries on (a kidnap); 'deaf on' loses every packet from the client (SIPs "
                 "still flow), 'deaf off' heals it; answered 'ok' or 'error: why'")
      ->capture_default_str();
  app.add_option("--model", model, "amigo | amigo-sh (built-in parameters)")->capture_default_str();
  app.add_option("--robot-params", params_file, "robot parameter YAML instead of the built-in set");
  app.add_option("--world", world_file, "world YAML (world/world.h): disks, walls, polygons for the sonar; the initial pose");
  app.add_option("--name", name, "SYNC2 robot name (default amigo-emulator, MobileSim in simulator mode)");
  app.add_option("--odometry-noise", robot.odometry_noise,
                 "relative std-dev of the wheel speeds the firmware integrates")->capture_default_str();
  app.add_option("--seed", seed, "noise seed (odometry and line corruption)")->capture_default_str();
  app.add_option("--time-scale", server.time_scale, "emulated seconds per wall second")->capture_default_str();
  app.add_option("--corrupt", server.corrupt_probability,
                 "noisy line: each robot packet is damaged with this probability")->capture_default_str();
  app.add_option("--left-open-at", robot.left_open_at_baud,
                 "start open and talking at this baud, as a crashed session that had switched it leaves the "
                 "robot (pty only; CLOSE returns it to 9600)");
  app.add_option("--command-log", command_log, "journal of every motion command received: 't command v w' per line");
  app.add_option("--exit-report", exit_report,
                 "file that says why the emulator stopped: 'running pid N' while it serves, then 'exit CODE: reason'");
  app.add_flag("--simulator-mode", robot.simulator_mode,
               "behave like an ARIA simulator (MobileSim): motors start enabled, SIPs always 0x32, watchdog "
               "only warns, CLOSE drops the connection");
  app.footer("Prints 'READY tcp=PORT status=PORT pty=PATH [control=PORT]' on stdout once it listens.");
  std::vector<std::string> args = amigobot_tracking::core::ownArguments(argc, argv);
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;  // --help: 0; a bad option: 2, as the usage errors before
  }
  robot.seed = server.corrupt_seed = seed;
  report(exit_report, "starting pid " + std::to_string(::getpid()));
  try {
    robot.robot = params_file.empty() ? builtinRobotParams(model) : loadRobotParams(params_file);
    if (!world_file.empty()) {
      const amigobot_tracking::world::World room = amigobot_tracking::world::loadWorld(world_file);
      robot.world = room;
      if (room.initial_pose) robot.initial_pose = *room.initial_pose;
    }
    robot.name = !name.empty() ? name : (robot.simulator_mode ? "MobileSim" : "amigo-emulator");
    RobotEmulator emulator(robot);
    std::ofstream journal;
    if (!command_log.empty()) {
      journal.open(command_log);
      if (!journal) throw std::runtime_error("amigobot_emulator: --command-log: cannot write " + command_log);
      emulator.setCommandLog(&journal);
    }
    EmulatorServer io(emulator, server);
    io.open();
    TeleportMailbox teleports;
    std::unique_ptr<ControlServer> control;
    if (control_port >= 0) {
      control = std::make_unique<ControlServer>(teleports, server.bind_address, control_port);
      emulator.setTeleportMailbox(&teleports);
    }
    const std::atomic<bool>& stop = amigobot_tracking::link::stopOnSignals();
    std::printf("READY tcp=%d status=%d pty=%s%s\n", io.tcpPort(), io.statusPort(),
                io.ptyName().empty() ? "-" : io.ptyName().c_str(),
                control ? (" control=" + std::to_string(control->port())).c_str() : "");
    std::fflush(stdout);
    report(exit_report, "running pid " + std::to_string(::getpid()));
    io.run(stop);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    report(exit_report, std::string("exit 1: ") + e.what());
    return 1;
  }
  const int stop_signal = amigobot_tracking::link::stopSignal();
  report(exit_report, stop_signal ? "exit 0: stopped by signal " + std::to_string(stop_signal)
                                  : std::string("exit 0: asked to quit on the status socket"));
  return 0;
}
