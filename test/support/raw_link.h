// Test helper: a raw byte link to the laser emulator (a TCP socket or a pseudo-terminal), to
// replay a standard driver's requests byte for byte and read the replies as it reads them.
#pragma once

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <stdexcept>
#include <string>

namespace amigobot_test {

class RawLink {
 public:
  // "127.0.0.1:PORT" or a pty path.
  explicit RawLink(const std::string& address) {
    const std::size_t colon = address.rfind(':');
    if (address[0] != '/' && colon != std::string::npos) {
      fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
      sockaddr_in addr{};
      addr.sin_family = AF_INET;
      addr.sin_port = htons(static_cast<std::uint16_t>(std::stoi(address.substr(colon + 1))));
      ::inet_pton(AF_INET, address.substr(0, colon).c_str(), &addr.sin_addr);
      if (::connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) < 0) throw std::runtime_error("connect " + address);
    } else {
      fd_ = ::open(address.c_str(), O_RDWR | O_NOCTTY);
      if (fd_ < 0) throw std::runtime_error("open " + address);
      termios tio{};
      ::tcgetattr(fd_, &tio);
      ::cfmakeraw(&tio);
      ::tcsetattr(fd_, TCSANOW, &tio);
    }
  }
  ~RawLink() { ::close(fd_); }
  RawLink(const RawLink&) = delete;
  RawLink& operator=(const RawLink&) = delete;

  void write(const std::string& bytes) {
    if (::write(fd_, bytes.data(), bytes.size()) != static_cast<ssize_t>(bytes.size())) throw std::runtime_error("write");
  }
  // Exactly `count` bytes, or fewer when `timeout` [s] passed.
  std::string read(std::size_t count, double timeout = 3.0) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(timeout * 1000.0));
    while (buffer_.size() < count && fill(end)) {
    }
    const std::string out = buffer_.substr(0, count);
    buffer_.erase(0, out.size());
    return out;
  }
  // Up to and including `delimiter`; empty when it did not come within `timeout` [s].
  std::string readUntil(char delimiter, double timeout = 3.0) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(timeout * 1000.0));
    std::size_t at;
    while ((at = buffer_.find(delimiter)) == std::string::npos) {
      if (!fill(end)) return "";
    }
    const std::string out = buffer_.substr(0, at + 1);
    buffer_.erase(0, at + 1);
    return out;
  }
  void discard() { buffer_.clear(); }

 private:
  bool fill(std::chrono::steady_clock::time_point end) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left)) <= 0) return false;
    char chunk[4096];
    const ssize_t n = ::read(fd_, chunk, sizeof(chunk));
    if (n <= 0) return false;
    buffer_.append(chunk, static_cast<std::size_t>(n));
    return true;
  }

  int fd_ = -1;
  std::string buffer_;
};

}  // namespace amigobot_test
