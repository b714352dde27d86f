// amigobot_emulator: a ROS-free AmigoBot stand-in that speaks the robot's protocol over
// TCP and a pseudo-terminal and reports its ground-truth pose on a status socket.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/aria/emulator_server.h"

using namespace amigobot_tracking::aria;

namespace {

std::atomic<bool> g_stop{false};
void onSignal(int) { g_stop = true; }

const char* kUsage =
    "usage: amigobot_emulator [options]\n"
    "  --tcp-port N        robot port over TCP (default 8101; 0 = any free port; -1 = none)\n"
    "  --bind ADDR         IPv4 address to listen on (default 127.0.0.1)\n"
    "  --pty LINK          also serve a pseudo-terminal, symlinked at LINK\n"
    "  --status-port N     ground-truth status socket (0 = any free port; default none):\n"
    "                      send any line, get 't x y theta v w motors open watchdog'\n"
    "  --model M           amigo | amigo-sh (built-in parameters; default amigo)\n"
    "  --robot-params FILE robot parameter YAML instead of the built-in set\n"
    "  --world FILE        obstacles (disks) for the sonar and an optional initial pose\n"
    "  --name NAME         SYNC2 robot name\n"
    "  --odometry-noise S  relative std-dev of the wheel speeds the firmware integrates\n"
    "  --seed N            noise seed (default 1)\n"
    "  --time-scale K      emulated seconds per wall second (default 1)\n"
    "  --corrupt P         noisy line: each robot packet is damaged with probability P\n"
    "  --command-log FILE  journal of every motion command received: 't command v w' per line\n"
    "  --simulator-mode    behave like an ARIA simulator (MobileSim): motors start enabled,\n"
    "                      SIPs always 0x32, watchdog only warns, CLOSE drops the connection\n"
    "Prints 'READY tcp=PORT status=PORT pty=PATH' on stdout once it listens.\n";

double number(const std::string& flag, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0') {
    std::cerr << "amigobot_emulator: " << flag << ": '" << text << "' is not a number\n";
    std::exit(2);
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  EmulatorOptions robot;
  EmulatorServerOptions server;
  std::string model = "amigo", params_file, world_file, name, command_log;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::cerr << "amigobot_emulator: " << a << " needs a value\n" << kUsage;
        std::exit(2);
      }
      return argv[++i];
    };
    if (a.find(":=") != std::string::npos) continue;  // ROS remappings roslaunch appends (__name:=, __log:=)
    if (a == "--tcp-port") server.tcp_port = static_cast<int>(number(a, value()));
    else if (a == "--bind") server.bind_address = value();
    else if (a == "--pty") server.pty_link = value();
    else if (a == "--status-port") server.status_port = static_cast<int>(number(a, value()));
    else if (a == "--model") model = value();
    else if (a == "--robot-params") params_file = value();
    else if (a == "--world") world_file = value();
    else if (a == "--name") name = value();
    else if (a == "--odometry-noise") robot.odometry_noise = number(a, value());
    else if (a == "--seed") robot.seed = server.corrupt_seed = static_cast<std::uint32_t>(number(a, value()));
    else if (a == "--time-scale") server.time_scale = number(a, value());
    else if (a == "--corrupt") server.corrupt_probability = number(a, value());
    else if (a == "--command-log") command_log = value();
    else if (a == "--simulator-mode") robot.simulator_mode = true;
    else if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      return 0;
    } else {
      std::cerr << "amigobot_emulator: unknown option '" << a << "'\n" << kUsage;
      return 2;
    }
  }
  try {
    robot.robot = params_file.empty() ? builtinRobotParams(model) : loadRobotParams(params_file);
    if (!world_file.empty()) loadWorld(world_file, robot);
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
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::signal(SIGPIPE, SIG_IGN);
    std::printf("READY tcp=%d status=%d pty=%s\n", io.tcpPort(), io.statusPort(),
                io.ptyName().empty() ? "-" : io.ptyName().c_str());
    std::fflush(stdout);
    io.run(g_stop);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
