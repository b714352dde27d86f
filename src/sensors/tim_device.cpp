// SICK TiM5xx over CoLa-A through MRPT's TCP socket. Not MRPT's CSICKTim561Eth: that one
// polls while the scanner streams, parses an unterminated buffer and drops the telegram's
// starting angle, angular step and scale factor; the geometry here comes from each telegram.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <mrpt/comms/CClientTCPSocket.h>

#include "amigobot_tracking/sensors/cola_a.h"
#include "amigobot_tracking/sensors/laser_device.h"
#include "amigobot_tracking/sensors/transport_address.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

constexpr double kTenThousandthDegree = M_PI / 180.0 / 10000.0;
constexpr double kRangeMin = 0.05, kRangeMax = 10.0;  // [m] TiM5xx data sheet

class TimDevice : public LaserDevice {
 public:
  explicit TimDevice(const std::string& port) : port_(port) {
    std::string host;
    int tcp_port = 0;
    if (!splitTcpAddress(port, &host, &tcp_port)) {
      throw std::invalid_argument("port: sick_tim5xx needs host:port (CoLa-A over TCP, usually :2111), got '" + port + "'");
    }
    try {
      socket_.connect(host, static_cast<unsigned short>(tcp_port), 2000);
      socket_.setTCPNoDelay(1);
    } catch (const std::exception& e) {
      throw std::runtime_error("sick_tim5xx " + port + ": cannot connect");
    }
    const std::string ident = request("sRN DeviceIdent"), serial = request("sRN SerialNumber");
    identity_ = "SICK " + ident.substr(std::min(ident.size(), std::size_t{4})) + ", " + serial.substr(std::min(serial.size(), std::size_t{4})) + " at " + port;
    if (request("sEN LMDscandata 1") != "sEA LMDscandata 1") throw std::runtime_error("sick_tim5xx " + port + ": scan output not enabled");
  }

  bool read(LaserScanData* scan, int timeout_ms) override {
    std::string body;
    if (!next(&body, timeout_ms)) return false;
    const double received = systemSeconds();
    if (body.rfind("sSN LMDscandata", 0) != 0) return false;  // an answer nobody waits for
    cola::ScanTelegram t;
    const std::string error = cola::decodeScan(body, &t);
    if (!error.empty()) throw ScanError("sick_tim5xx " + port_ + ": " + error);
    if (t.scan_frequency == 0 || t.angular_step == 0 || t.ranges.empty()) {
      throw std::runtime_error("sick_tim5xx " + port_ + ": scan telegram without frequency or geometry");
    }
    LaserScanData out;
    out.angle_min = t.start_angle * kTenThousandthDegree - M_PI / 2.0;  // SICK's 0 deg is the device's +y
    out.angle_increment = t.angular_step * kTenThousandthDegree;
    out.scan_time = 100.0 / t.scan_frequency;
    out.time_increment = t.measurement_frequency > 0 ? 1.0 / (100.0 * t.measurement_frequency) : 0.0;
    out.range_min = kRangeMin;
    out.range_max = kRangeMax;
    out.ranges.reserve(t.ranges.size());
    for (std::uint32_t value : t.ranges) {
      out.ranges.push_back(value == 0 ? std::numeric_limits<float>::infinity()
                                      : static_cast<float>(value * t.scale_factor / 1000.0));
    }
    out.stamp = received - out.time_increment * static_cast<double>(t.ranges.size() - 1);
    *scan = std::move(out);
    return true;
  }

  std::string identity() const override { return identity_; }

 private:
  std::string request(const std::string& body) {
    const std::string telegram = cola::frame(body);
    if (socket_.writeAsync(telegram.data(), telegram.size(), 1000) != telegram.size()) {
      throw std::runtime_error("sick_tim5xx " + port_ + ": write failed");
    }
    std::string answer;
    if (!next(&answer, 2000)) throw std::runtime_error("sick_tim5xx " + port_ + ": no answer to '" + body + "'");
    return answer;
  }

  // The next telegram within timeout_ms; throws when the connection is gone.
  bool next(std::string* body, int timeout_ms) {
    const double end = systemSeconds() + timeout_ms / 1000.0;
    while (!cola::nextTelegram(&buffer_, body)) {
      if (buffer_.size() > 1 << 20) throw std::runtime_error("sick_tim5xx " + port_ + ": no ETX in 1 MiB");
      const int left = static_cast<int>((end - systemSeconds()) * 1000.0);
      if (left <= 0) return false;
      char chunk[8192];
      const std::size_t n = socket_.readAsync(chunk, sizeof(chunk), left, 2);
      if (n == 0 && !socket_.isConnected()) throw std::runtime_error("sick_tim5xx " + port_ + ": connection closed");
      buffer_.append(chunk, n);
    }
    return true;
  }

  std::string port_, identity_, buffer_;
  mrpt::comms::CClientTCPSocket socket_;
};

}  // namespace

std::unique_ptr<LaserDevice> openTim(const std::string& port) { return std::make_unique<TimDevice>(port); }

}  // namespace sensors
}  // namespace amigobot_tracking
