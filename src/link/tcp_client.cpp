#include "amigobot_tracking/link/tcp_client.h"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace amigobot_tracking {
namespace link {
namespace {

// Milliseconds left until `end` on the steady clock, never below 0.
int msLeft(std::chrono::steady_clock::time_point end) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now()).count();
  return left > 0 ? static_cast<int>(left) : 0;
}

// Connects the non-blocking socket `fd` to `ai` within timeout_ms: 0, or the errno.
int connectWithin(int fd, const addrinfo& ai, int timeout_ms) {
  if (::connect(fd, ai.ai_addr, ai.ai_addrlen) == 0) return 0;
  if (errno != EINPROGRESS) return errno;
  pollfd p{fd, POLLOUT, 0};
  const int ready = ::poll(&p, 1, timeout_ms);
  if (ready < 0) return errno;
  if (ready == 0) return ETIMEDOUT;
  int error = 0;
  socklen_t length = sizeof(error);
  if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) < 0) return errno;
  return error;
}

}  // namespace

TcpClient::~TcpClient() { close(); }

void TcpClient::connect(const TcpAddress& address, int timeout_ms) {
  close();
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const int resolved = ::getaddrinfo(address.host.c_str(), std::to_string(address.port).c_str(), &hints, &found);
  if (resolved != 0) throw std::runtime_error(std::string("cannot resolve ") + address.host + ": " + ::gai_strerror(resolved));
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  int error = ENOENT;
  for (const addrinfo* ai = found; ai && fd_ < 0; ai = ai->ai_next) {
    const int fd = ::socket(ai->ai_family, ai->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, ai->ai_protocol);
    if (fd < 0) {
      error = errno;
      continue;
    }
    error = connectWithin(fd, *ai, msLeft(end));
    if (error == 0) {
      fd_ = fd;
    } else {
      ::close(fd);
    }
  }
  ::freeaddrinfo(found);
  if (fd_ < 0) throw std::runtime_error(std::strerror(error));
  const int one = 1;
  ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));  // small requests leave at once
}

void TcpClient::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::size_t TcpClient::read(void* buffer, std::size_t size, int first_timeout_ms, int between_timeout_ms) {
  auto* bytes = static_cast<char*>(buffer);
  std::size_t done = 0;
  while (fd_ >= 0 && done < size) {
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, std::max(0, done == 0 ? first_timeout_ms : between_timeout_ms));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) break;
    const ssize_t n = ready < 0 ? -1 : ::recv(fd_, bytes + done, size - done, 0);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      continue;
    } else {
      close();  // the peer closed the connection (0) or the socket failed
    }
  }
  return done;
}

std::size_t TcpClient::write(const void* data, std::size_t size, int timeout_ms) {
  const auto* bytes = static_cast<const char*>(data);
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  std::size_t done = 0;
  while (fd_ >= 0 && done < size) {
    const ssize_t n = ::send(fd_, bytes + done, size - done, MSG_NOSIGNAL);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) {
      close();
      break;
    }
    pollfd p{fd_, POLLOUT, 0};
    const int left = msLeft(end);
    if (left == 0 || (::poll(&p, 1, left) == 0)) break;
  }
  return done;
}

}  // namespace link
}  // namespace amigobot_tracking
