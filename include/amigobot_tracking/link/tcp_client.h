// The client side of a TCP byte link, shared by the robot's transport and the lasers' drivers
// (the CoLa-A client, the SCIP stream under MRPT's CHokuyoURG): connect within a time limit
// with Nagle off, read with MRPT's two timeouts (first byte, then silence between bytes), and
// write with MSG_NOSIGNAL, so a peer that closes the socket is an error of write(), never a
// SIGPIPE that kills the process.
#pragma once

#include <cstddef>
#include <string>

#include "amigobot_tracking/link/address.h"

namespace amigobot_tracking {
namespace link {

class TcpClient {
 public:
  TcpClient() = default;
  ~TcpClient();
  TcpClient(const TcpClient&) = delete;
  TcpClient& operator=(const TcpClient&) = delete;

  // Resolves and connects within timeout_ms, or throws std::runtime_error with the reason
  // (the resolver's or the system's): the caller names the device and its address.
  void connect(const TcpAddress& address, int timeout_ms);
  void close();
  // Open and not known to be closed by the peer (a read that saw the end of the stream or
  // an error closes it).
  bool isOpen() const { return fd_ >= 0; }
  // Waits up to first_timeout_ms for the first byte, then reads on until `size` bytes or
  // between_timeout_ms without one. Returns the bytes read; 0 with isOpen() false once the
  // peer closed the connection or the socket failed.
  std::size_t read(void* buffer, std::size_t size, int first_timeout_ms, int between_timeout_ms);
  // Sends within timeout_ms: the bytes sent, short of `size` on a timeout or a closed link.
  std::size_t write(const void* data, std::size_t size, int timeout_ms);

 private:
  int fd_ = -1;
};

}  // namespace link
}  // namespace amigobot_tracking
