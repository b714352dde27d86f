#include "amigobot_tracking/aria/transport.h"

#include <csignal>
#include <stdexcept>

#include <mrpt/comms/CClientTCPSocket.h>
#include <mrpt/comms/CSerialPort.h>

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr unsigned kConnectTimeoutMs = 2000;
constexpr int kWriteTimeoutMs = 1000;

class TcpTransport : public Transport {
 public:
  TcpTransport(std::string host, unsigned short port) : host_(std::move(host)), port_(port) {
    // A peer that closes the socket must surface as an error from send(), not kill the
    // process with SIGPIPE (MRPT's send() does not pass MSG_NOSIGNAL).
    std::signal(SIGPIPE, SIG_IGN);
  }
  void open() override {
    socket_ = std::make_unique<mrpt::comms::CClientTCPSocket>();
    try {
      socket_->connect(host_, port_, kConnectTimeoutMs);
    } catch (const std::exception& e) {
      socket_.reset();
      throw std::runtime_error(describe() + ": cannot connect: " + firstLine(e.what()));
    }
    socket_->setTCPNoDelay(1);
  }
  void close() override { socket_.reset(); }
  bool isOpen() override { return socket_ && socket_->isConnected(); }
  std::size_t read(std::uint8_t* buffer, std::size_t size, int timeout_ms) override {
    if (!isOpen()) throw std::runtime_error(describe() + ": connection closed");
    const std::size_t n = socket_->readAsync(buffer, size, timeout_ms, 0);
    if (n == 0 && !socket_->isConnected()) throw std::runtime_error(describe() + ": connection closed by the robot");
    return n;
  }
  void write(const std::vector<std::uint8_t>& bytes) override {
    if (!isOpen() || socket_->writeAsync(bytes.data(), bytes.size(), kWriteTimeoutMs) != bytes.size()) {
      throw std::runtime_error(describe() + ": write failed");
    }
  }
  bool isSerial() const override { return false; }
  void setBaud(int /*baud*/) override {}
  int baud() const override { return 0; }
  std::string describe() const override { return "tcp " + host_ + ":" + std::to_string(port_); }

 private:
  static std::string firstLine(const std::string& s) {
    const auto pos = s.find_last_of('\n', s.size() > 1 ? s.size() - 2 : 0);
    return pos == std::string::npos ? s : s.substr(pos + 1);
  }
  std::string host_;
  unsigned short port_;
  std::unique_ptr<mrpt::comms::CClientTCPSocket> socket_;
};

class SerialTransport : public Transport {
 public:
  SerialTransport(std::string device, int baud) : device_(std::move(device)), baud_(baud) {}
  void open() override {
    try {
      port_.open(device_);
      port_.setConfig(baud_);
      // Read() then waits up to this long when nothing arrives; the client's loop calls it
      // with its own period, so keep it short.
      port_.setTimeouts(0, 0, kReadTimeoutMs, 0, 0);
      port_.purgeBuffers();
    } catch (const std::exception& e) {
      port_.close();
      throw std::runtime_error(describe() + ": cannot open: " + std::string(e.what()).substr(0, 300));
    }
  }
  void close() override { port_.close(); }
  bool isOpen() override { return port_.isOpen(); }
  std::size_t read(std::uint8_t* buffer, std::size_t size, int /*timeout_ms*/) override {
    if (!port_.isOpen()) throw std::runtime_error(describe() + ": device closed (unplugged?)");
    return port_.Read(buffer, size);
  }
  void write(const std::vector<std::uint8_t>& bytes) override {
    try {
      if (port_.Write(bytes.data(), bytes.size()) != bytes.size()) throw std::runtime_error("short write");
    } catch (const std::exception& e) {
      throw std::runtime_error(describe() + ": write failed");
    }
  }
  bool isSerial() const override { return true; }
  void setBaud(int baud) override {
    try {
      port_.setConfig(baud);
      port_.purgeBuffers();  // bytes read at the old speed are garbage at the new one
    } catch (const std::exception& e) {
      throw std::runtime_error(describe() + ": cannot switch to " + std::to_string(baud) +
                               " baud: " + std::string(e.what()).substr(0, 300));
    }
    baud_ = baud;
  }
  int baud() const override { return baud_; }
  std::string describe() const override { return "serial " + device_ + " at " + std::to_string(baud_) + " baud"; }

 private:
  static constexpr int kReadTimeoutMs = 20;
  std::string device_;
  int baud_;
  mrpt::comms::CSerialPort port_;
};

}  // namespace

bool isTcpAddress(const std::string& port) {
  const auto colon = port.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 >= port.size()) return false;
  for (std::size_t i = colon + 1; i < port.size(); ++i) {
    if (port[i] < '0' || port[i] > '9') return false;
  }
  return port.front() != '/';
}

std::unique_ptr<Transport> makeTransport(const std::string& port, int baud) {
  if (port.empty()) throw std::invalid_argument("port: empty (expected /dev/ttyUSB0 or host:port)");
  if (isTcpAddress(port)) {
    const auto colon = port.rfind(':');
    const std::string digits = port.substr(colon + 1);
    const long number = digits.size() <= 5 ? std::stol(digits) : 0;
    if (number < 1 || number > 65535) throw std::invalid_argument("port: TCP port out of range in '" + port + "'");
    return std::make_unique<TcpTransport>(port.substr(0, colon), static_cast<unsigned short>(number));
  }
  if (baud <= 0) throw std::invalid_argument("baud: must be positive, got " + std::to_string(baud));
  return std::make_unique<SerialTransport>(port, baud);
}

}  // namespace aria
}  // namespace amigobot_tracking
