// Test helper: a node's executable as a child process whose terminal is either a real
// pseudo-terminal (posix_openpt; the child's stdin, stdout and stderr are the slave, its
// controlling terminal, and the test types into the master) or a pipe (stdin /dev/null).
// Everything the child writes is collected; the child is killed on scope exit.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace amigobot_test {

class NodeProcess {
 public:
  enum class Terminal { kPty, kPipe };

  NodeProcess() = default;
  NodeProcess(const NodeProcess&) = delete;
  NodeProcess& operator=(const NodeProcess&) = delete;
  ~NodeProcess() {
    stop(SIGKILL, 5.0);
    reading_ = false;
    if (reader_.joinable()) reader_.join();
    if (fd_ >= 0) ::close(fd_);
    if (slave_fd_ >= 0) ::close(slave_fd_);
  }

  void start(std::vector<std::string> args, Terminal terminal) {
    int child_fd = -1;
    if (terminal == Terminal::kPty) {
      fd_ = ::posix_openpt(O_RDWR | O_NOCTTY);
      if (fd_ < 0 || ::grantpt(fd_) != 0 || ::unlockpt(fd_) != 0) throw std::runtime_error("posix_openpt");
      slave_ = ::ptsname(fd_);
      // Held open here too, so the terminal's settings can still be read after the child exits.
      slave_fd_ = ::open(slave_.c_str(), O_RDWR | O_NOCTTY);
      if (slave_fd_ < 0 || ::tcgetattr(slave_fd_, &initial_) != 0) throw std::runtime_error("open " + slave_);
    } else {
      int out[2];
      if (::pipe(out) < 0) throw std::runtime_error("pipe");
      fd_ = out[0];
      child_fd = out[1];
    }
    pid_ = ::fork();
    if (pid_ == 0) {
      int in = child_fd;
      if (terminal == Terminal::kPty) {
        ::setsid();  // a session of its own: the slave becomes its controlling terminal
        child_fd = in = ::open(slave_.c_str(), O_RDWR);
      } else {
        in = ::open("/dev/null", O_RDONLY);
      }
      ::close(fd_);
      if (slave_fd_ >= 0) ::close(slave_fd_);
      ::dup2(in, STDIN_FILENO);
      ::dup2(child_fd, STDOUT_FILENO);
      ::dup2(child_fd, STDERR_FILENO);
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      std::_Exit(127);
    }
    if (child_fd >= 0) ::close(child_fd);
    reading_ = true;
    reader_ = std::thread([this] { readLoop(); });
  }

  // Writes to the pty master: the child reads it as typed keys.
  void type(const std::string& keys) const {
    if (::write(fd_, keys.data(), keys.size()) != static_cast<ssize_t>(keys.size())) throw std::runtime_error("type");
  }
  // The terminal's settings as the child sees them (pty mode).
  termios terminalSettings() const {
    termios t{};
    if (::tcgetattr(slave_fd_, &t) != 0) throw std::runtime_error("tcgetattr on " + slave_);
    return t;
  }
  // The settings of the fresh pty, before the child started.
  const termios& initialTerminalSettings() const { return initial_; }
  std::string output() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return output_;
  }
  // Waits until the output contains `text`.
  bool waitForOutput(const std::string& text, double timeout) const {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
    while (std::chrono::steady_clock::now() < end) {
      if (output().find(text) != std::string::npos) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  void signal(int signal) const {
    if (pid_ > 0) ::kill(pid_, signal);
  }
  // Waits for the child's exit: its exit code, or -1 when it did not exit within `timeout`
  // or died of a signal.
  int waitExit(double timeout) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
    while (pid_ > 0 && std::chrono::steady_clock::now() < end) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return -1;
  }
  void stop(int signal, double timeout) {
    if (pid_ <= 0) return;
    ::kill(pid_, signal);
    if (waitExit(timeout) == -1 && pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
      pid_ = -1;
    }
  }

 private:
  void readLoop() {
    char buffer[512];
    while (reading_) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      const ssize_t n = ::read(fd_, buffer, sizeof(buffer));
      if (n <= 0) {  // the child is gone (EIO on a pty master, EOF on a pipe)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        continue;
      }
      std::lock_guard<std::mutex> lock(mutex_);
      output_.append(buffer, static_cast<size_t>(n));
    }
  }

  pid_t pid_ = -1;
  int fd_ = -1, slave_fd_ = -1;
  termios initial_{};
  std::string slave_;
  std::thread reader_;
  std::atomic<bool> reading_{false};
  mutable std::mutex mutex_;
  std::string output_;
};

}  // namespace amigobot_test
