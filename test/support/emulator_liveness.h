// Why the emulated robot does not answer, for the end-to-end tests' failure messages:
// roslaunch starts amigobot_emulator with output="log", so its stderr never reaches the test.
// test/e2e/include/emulated_robot.launch passes it --exit-report at emulatorExitReportPath(its
// status port); the emulator writes there "running pid N" while it serves and "exit CODE: why"
// when it stops. Together with a look for the process itself this says whether the emulator is
// alive, exited (and why), or never started.
#pragma once

#include <dirent.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace e2e {

// The convention emulated_robot.launch follows: one file per status port (a port is unique
// among the emulators running at one time on the machine).
inline std::string emulatorExitReportPath(int status_port) {
  return "/tmp/amigobot_emulator_status" + std::to_string(status_port) + ".exit";
}

// The process id of a running amigobot_emulator whose arguments hold `--status-port PORT`; -1
// if there is none.
inline int emulatorPid(int status_port) {
  DIR* proc = ::opendir("/proc");
  if (!proc) return -1;
  int found = -1;
  const std::string port = std::to_string(status_port);
  while (dirent* entry = ::readdir(proc)) {
    const std::string pid = entry->d_name;
    if (pid.empty() || !std::all_of(pid.begin(), pid.end(), [](unsigned char c) { return std::isdigit(c); })) continue;
    std::ifstream in("/proc/" + pid + "/cmdline", std::ios::binary);
    const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> args;
    std::string arg;
    for (char c : raw) {
      if (c == '\0') {
        args.push_back(arg);
        arg.clear();
      } else {
        arg += c;
      }
    }
    if (args.empty() || args[0].find("amigobot_emulator") == std::string::npos) continue;
    for (std::size_t i = 0; i + 1 < args.size(); ++i) {
      if (args[i] == "--status-port" && args[i + 1] == port) found = std::stoi(pid);
    }
    if (found > 0) break;
  }
  ::closedir(proc);
  return found;
}

// One sentence on the emulator of `status_port`: running (with its pid), or not running and
// what its exit report says.
inline std::string emulatorState(int status_port) {
  const std::string path = emulatorExitReportPath(status_port);
  std::ifstream in(path);
  std::string report;
  std::getline(in, report);
  const int pid = emulatorPid(status_port);
  if (pid > 0) return "amigobot_emulator (pid " + std::to_string(pid) + ") is running";
  if (!in) return "no amigobot_emulator with --status-port " + std::to_string(status_port) +
                  " is running and it left no exit report (" + path + "): it never started";
  if (report.rfind("exit", 0) == 0) return "amigobot_emulator is not running; its exit report says '" + report + "'";
  return "amigobot_emulator is not running and its exit report says '" + report +
         "': it was killed (a signal it could not catch) or crashed";
}

}  // namespace e2e
