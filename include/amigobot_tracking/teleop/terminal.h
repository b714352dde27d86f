// The operator's terminal in raw mode for keyboard tele-operation: keys arrive one by one,
// unechoed, without Enter. Ctrl-C still raises SIGINT (ISIG kept), so the node's own
// handler stops the robot. The original settings come back on every way out: the
// destructor, restore(), and an atexit hook for exit() paths.
#pragma once

#include <termios.h>

#include <string>

namespace amigobot_tracking {
namespace teleop {

class RawTerminal {
 public:
  // Throws std::runtime_error naming the problem when `fd` is not a terminal.
  explicit RawTerminal(int fd);
  ~RawTerminal();
  RawTerminal(const RawTerminal&) = delete;
  RawTerminal& operator=(const RawTerminal&) = delete;

  // Puts the saved settings back (idempotent; async-signal-safe).
  static void restore();

  // Reads the bytes waiting on the terminal, waiting at most timeout_ms for the first.
  // Returns false when the terminal is gone (hang-up, read error).
  bool readKeys(int timeout_ms, std::string* keys) const;

 private:
  int fd_;
};

}  // namespace teleop
}  // namespace amigobot_tracking
