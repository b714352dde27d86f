#include "amigobot_tracking/ros/xmlrpc_call.h"

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "amigobot_tracking/link/system_clock_errors.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace {

// Waits for `events` on fd until `deadline`; false on timeout or error.
bool waitFor(int fd, short events, double deadline) {
  const double left = deadline - link::steadySeconds();
  if (left <= 0.0) return false;
  pollfd p{fd, events, 0};
  return ::poll(&p, 1, static_cast<int>(left * 1e3) + 1) > 0 && (p.revents & (events | POLLHUP | POLLERR));
}

class Socket {
 public:
  explicit Socket(int fd) : fd_(fd) {}
  ~Socket() {
    if (fd_ >= 0) ::close(fd_);
  }
  int fd() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

bool splitHttpUri(const std::string& uri, std::string* host, int* port) {
  const std::string scheme = "http://";
  if (uri.rfind(scheme, 0) != 0) return false;
  const std::string rest = uri.substr(scheme.size());
  const std::size_t colon = rest.find(':');
  if (colon == std::string::npos || colon == 0) return false;
  *host = rest.substr(0, colon);
  *port = std::atoi(rest.c_str() + colon + 1);
  return *port > 0 && *port < 65536;
}

std::string callXmlRpc(const std::string& host, int port, const std::string& method,
                       const XmlRpc::XmlRpcValue& params, double timeout, XmlRpc::XmlRpcValue* result) {
  const double deadline = link::steadySeconds() + timeout;
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || !found) {
    return "cannot resolve " + host;
  }
  Socket sock(::socket(found->ai_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  const int rc = sock.fd() < 0 ? -1 : ::connect(sock.fd(), found->ai_addr, found->ai_addrlen);
  ::freeaddrinfo(found);
  if (sock.fd() < 0 || (rc < 0 && errno != EINPROGRESS)) return std::string("connect: ") + std::strerror(errno);
  if (!waitFor(sock.fd(), POLLOUT, deadline)) return "connect: timed out";
  int error = 0;
  socklen_t len = sizeof(error);
  ::getsockopt(sock.fd(), SOL_SOCKET, SO_ERROR, &error, &len);
  if (error != 0) return std::string("connect: ") + std::strerror(error);

  std::string body = "<?xml version=\"1.0\"?>\r\n<methodCall><methodName>" + method + "</methodName>\r\n<params>";
  for (int i = 0; i < params.size(); ++i) body += "<param>" + params[i].toXml() + "</param>";
  body += "</params></methodCall>\r\n";
  const std::string request = "POST / HTTP/1.1\r\nUser-Agent: amigobot_tracking\r\nHost: " + host +
                              "\r\nContent-Type: text/xml\r\nContent-length: " + std::to_string(body.size()) +
                              "\r\n\r\n" + body;
  std::size_t sent = 0;
  while (sent < request.size()) {
    if (!waitFor(sock.fd(), POLLOUT, deadline)) return "send: timed out";
    const ssize_t n = ::send(sock.fd(), request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
    if (n <= 0 && errno != EAGAIN) return std::string("send: ") + std::strerror(errno);
    if (n > 0) sent += static_cast<std::size_t>(n);
  }
  std::string reply;
  while (reply.find("</methodResponse>") == std::string::npos) {
    if (!waitFor(sock.fd(), POLLIN, deadline)) return "no answer within " + std::to_string(timeout).substr(0, 4) + " s";
    char buffer[4096];
    const ssize_t n = ::recv(sock.fd(), buffer, sizeof(buffer), 0);
    if (n == 0) return "connection closed before the answer";
    if (n < 0 && errno != EAGAIN) return std::string("recv: ") + std::strerror(errno);
    if (n > 0) reply.append(buffer, static_cast<std::size_t>(n));
    if (reply.size() > (1u << 24)) return "answer larger than 16 MB";
  }
  int offset = static_cast<int>(reply.find("<value>"));
  if (offset < 0 || reply.find("<fault>") != std::string::npos) return "fault or no value in the answer to " + method;
  XmlRpc::XmlRpcValue value;
  if (!value.fromXml(reply, &offset)) return "unreadable answer to " + method;
  *result = value;
  return "";
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
