// The server side of an emulated device's link, shared by the robot and laser emulators: a
// TCP port that serves one client at a time (a device has one host: the newest connection
// replaces the old one) and a pseudo-terminal behind a stable symlink (the device's serial
// or USB-ACM port). Plain POSIX sockets, as link::TcpClient (tcp_client.h) on the client
// side; this is the stack's one listening socket (the emulators' device ports and the robot
// emulator's control socket). The emulators keep their own poll() loops (each has its own
// extra descriptors and timing); this is what they share. Errors are std::runtime_error naming the address or path.
#pragma once

#include <cstddef>
#include <string>

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

// Sends what the peer takes now and drops the rest, as a device's output buffer overflows
// when its host does not read; works on sockets (no SIGPIPE) and on a pty master.
void sendAvailable(int fd, const void* data, std::size_t size);

}  // namespace link
}  // namespace amigobot_tracking
