#include "amigobot_tracking/aria/transport.h"

#include <optional>
#include <stdexcept>

#include "amigobot_tracking/link/address.h"
#include "amigobot_tracking/link/serial_port.h"
#include "amigobot_tracking/link/tcp_client.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr int kConnectTimeoutMs = 2000;
constexpr int kWriteTimeoutMs = 1000;

class TcpTransport : public Transport {
 public:
  // A peer that closes the socket is an error of write(): link::TcpClient sends without SIGPIPE.
  explicit TcpTransport(link::TcpAddress address) : address_(std::move(address)) {}
  void open() override {
    try {
      socket_.connect(address_, kConnectTimeoutMs);
    } catch (const std::exception& e) {
      throw std::runtime_error(describe() + ": cannot connect: " + e.what());
    }
  }
  void close() override { socket_.close(); }
  bool isOpen() override { return socket_.isOpen(); }
  std::size_t read(std::uint8_t* buffer, std::size_t size, int timeout_ms) override {
    if (!isOpen()) throw std::runtime_error(describe() + ": connection closed");
    const std::size_t n = socket_.read(buffer, size, timeout_ms, 0);
    if (n == 0 && !socket_.isOpen()) throw std::runtime_error(describe() + ": connection closed by the robot");
    return n;
  }
  void write(const std::vector<std::uint8_t>& bytes) override {
    if (!isOpen() || socket_.write(bytes.data(), bytes.size(), kWriteTimeoutMs) != bytes.size()) {
      throw std::runtime_error(describe() + ": write failed");
    }
  }
  bool isSerial() const override { return false; }
  void setBaud(int /*baud*/) override {}
  int baud() const override { return 0; }
  std::string describe() const override { return "tcp " + link::formatTcpAddress(address_); }

 private:
  link::TcpAddress address_;
  link::TcpClient socket_;
};

class SerialTransport : public Transport {
 public:
  SerialTransport(std::string device, int baud) : device_(std::move(device)), baud_(baud) {}
  void open() override { port_.open(device_, baud_); }
  void close() override { port_.close(); }
  bool isOpen() override { return port_.isOpen(); }
  std::size_t read(std::uint8_t* buffer, std::size_t size, int timeout_ms) override {
    return port_.read(buffer, size, timeout_ms);
  }
  void write(const std::vector<std::uint8_t>& bytes) override { port_.write(bytes.data(), bytes.size(), kWriteTimeoutMs); }
  bool isSerial() const override { return true; }
  void setBaud(int baud) override {
    port_.setBaud(baud);
    baud_ = baud;
  }
  int baud() const override { return baud_; }
  std::string describe() const override { return "serial " + device_ + " at " + std::to_string(baud_) + " baud"; }

 private:
  std::string device_;
  int baud_;
  link::SerialPort port_;  // raw 8N1; its errors name the device and the baud
};

}  // namespace

std::unique_ptr<Transport> makeTransport(const std::string& port, int baud) {
  std::optional<link::TcpAddress> tcp;
  try {
    tcp = link::parseTcpAddress(port);  // the one address rule
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("port: ") + e.what());
  }
  if (tcp) return std::make_unique<TcpTransport>(*tcp);
  if (baud <= 0) throw std::invalid_argument("baud: must be positive, got " + std::to_string(baud));
  return std::make_unique<SerialTransport>(port, baud);
}

}  // namespace aria
}  // namespace amigobot_tracking
