// The server side of an emulated device's link, shared by the robot and laser emulators: a
// TCP port that serves one client at a time (a device has one host: the newest connection
// replaces the old one) and a pseudo-terminal behind a stable symlink (the device's serial
// or USB-ACM port). Plain POSIX sockets, as link::TcpClient (tcp_client.h) on the client
// side; this is the stack's one listening socket (the emulators' device ports and the robot
// emulator's control socket). The emulators keep their own poll() loops (each has its own
// extra descriptors and timing); this is what they share. Errors are std::runtime_error naming the address or path.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "amigobot_tracking/link/system_clock_errors.h"  // steadySeconds, systemError: the emulators use both

namespace amigobot_tracking {
namespace link {

// A listening IPv4 TCP socket.
class TcpListener {
 public:
  TcpListener() = default;
  ~TcpListener();
  TcpListener(const TcpListener&) = delete;
  TcpListener& operator=(const TcpListener&) = delete;

  // Listens on bind_address:port (port 0: any free port, then port() tells which).
  void open(const std::string& bind_address, int port, int backlog = 4);
  bool isOpen() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  int port() const { return port_; }
  // The next waiting client (TCP_NODELAY, close-on-exec, non-blocking), or -1 when none.
  int accept() const;

 private:
  int fd_ = -1;
  int port_ = -1;
};

// A pseudo-terminal whose slave is reachable at a symlink, raw (no echo, no line
// discipline). The emulator holds a slave descriptor itself, so the pty survives clients
// opening and closing it, as a device's port does; the symlink is removed on destruction.
class PseudoTerminal {
 public:
  PseudoTerminal() = default;
  ~PseudoTerminal();
  PseudoTerminal(const PseudoTerminal&) = delete;
  PseudoTerminal& operator=(const PseudoTerminal&) = delete;

  // Opens the pty, sets its slave raw (at `baud` when > 0) and points `link_path` at it.
  void open(const std::string& link_path, int baud = 0);
  bool isOpen() const { return master_ >= 0; }
  int master() const { return master_; }  // the emulator's end (non-blocking)
  int slave() const { return slave_; }    // held open; its termios show the client's speed
  const std::string& name() const { return name_; }  // /dev/pts/N

 private:
  int master_ = -1, slave_ = -1;
  std::string name_, link_path_;
};

// The clients of a line-based socket (the robot emulator's status and control sockets): each
// descriptor with the bytes of its unfinished line. Closes them all on destruction.
class LineClients {
 public:
  LineClients() = default;
  ~LineClients();
  LineClients(const LineClients&) = delete;
  LineClients& operator=(const LineClients&) = delete;

  void add(int fd);
  std::size_t size() const { return fds_.size(); }
  int fd(std::size_t k) const { return fds_[k]; }
  // One read from client k (poll said it is ready; EAGAIN and EINTR are "nothing yet"); each
  // complete line goes to serve(fd, line), whose false ends the client. The client ends too
  // when it hung up or failed, or when its unfinished line exceeds max_line bytes (npos: no
  // bound). An ended client is closed at once and removed by sweep(), so indices hold for
  // the loop that calls read().
  void read(std::size_t k, const std::function<bool(int fd, const std::string& line)>& serve,
            std::size_t max_line = std::string::npos);
  void sweep();

 private:
  std::vector<int> fds_;
  std::vector<std::string> pending_;
};

// Sends what the peer takes now and drops the rest, as a device's output buffer overflows
// when its host does not read; works on sockets (no SIGPIPE) and on a pty master.
void sendAvailable(int fd, const void* data, std::size_t size);
inline void sendAvailable(int fd, const std::string& bytes) { sendAvailable(fd, bytes.data(), bytes.size()); }
inline void sendAvailable(int fd, const std::vector<std::uint8_t>& bytes) { sendAvailable(fd, bytes.data(), bytes.size()); }

// Moves the first complete line of `pending` (without its '\n') into `line`; false, and
// nothing taken, while no line is complete. The line framing of the status and control
// sockets, on both their ends.
bool takeLine(std::string& pending, std::string* line);

// An emulator process's signals: SIGINT and SIGTERM set the returned flag (its run loop's
// `stop`), stopSignal() then says which; SIGPIPE is ignored, so a client that hangs up is an
// error of that send, not the emulator's death.
const std::atomic<bool>& stopOnSignals();
int stopSignal();  // 0 while no stop signal came

}  // namespace link
}  // namespace amigobot_tracking
