// SICK TiM5xx and LMS1xx over CoLa-A through link::TcpClient. Not MRPT's CSICKTim561Eth
// nor CLMS100Eth: both poll with sRN LMDscandata and parse what one read returned, without
// looking for the ETX, and drop the telegram's starting angle, angular step and scale factor
// (CLMS100Eth also rewrites the device's scan configuration to 0.25 deg and sleeps 10 s per
// status poll); the geometry here comes from each telegram. The LMS1xx is first logged in as authorised client, asked for
// its scan configuration (LMPscancfg, kept in the identity) and started (LMCstartmeas, Run,
// then STlms until "ready for measurement"), as its telegram listing describes.
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "amigobot_tracking/link/address.h"
#include "amigobot_tracking/link/tcp_client.h"
#include "amigobot_tracking/sensors/cola_a.h"
#include "amigobot_tracking/sensors/cola_protocol.h"
#include "amigobot_tracking/sensors/laser_device.h"
#include "amigobot_tracking/sensors/laser_model.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

constexpr double kTenThousandthDegree = M_PI / 180.0 / 10000.0;

std::vector<std::string> fields(const std::string& body) {
  std::istringstream in(body);
  std::vector<std::string> out;
  for (std::string f; in >> f;) out.push_back(f);
  return out;
}

class ColaDevice : public LaserDevice {
 public:
  ColaDevice(const std::string& model, const std::string& port) : port_(port), model_(laserModel(model)) {
    const std::optional<link::TcpAddress> tcp = link::parseTcpAddress(port);
    if (!tcp) {
      throw std::invalid_argument("port: " + model + " needs host:port (CoLa-A over TCP: :2111, or :2112 as sick_tim and sick_scan), got '" + port + "'");
    }
    try {
      socket_.connect(*tcp, 2000);
    } catch (const std::exception& e) {
      throw std::runtime_error(model + " " + port + ": cannot connect: " + e.what());
    }
    const std::string ident = request("sRN DeviceIdent"), serial = request("sRN SerialNumber");
    identity_ = "SICK " + ident.substr(std::min(ident.size(), std::size_t{4})) + ", " + serial.substr(std::min(serial.size(), std::size_t{4}));
    if (model_.protocolGeometry<ColaGeometry>().measures_on_command) startLms();
    identity_ += " at " + port;
    if (request("sEN LMDscandata 1") != "sEA LMDscandata 1") throw std::runtime_error(model + " " + port + ": scan output not enabled");
  }

  bool read(LaserScanData* scan, int timeout_ms) override {
    std::string body;
    if (!next(&body, timeout_ms)) return false;
    const double received = systemSeconds();
    if (body.rfind("sSN LMDscandata", 0) != 0) return false;  // an answer nobody waits for
    cola::ScanTelegram t;
    const std::string error = cola::decodeScan(body, &t);
    if (!error.empty()) throw ScanError(model_.name + " " + port_ + ": " + error);
    if (t.scan_frequency == 0 || t.angular_step == 0 || t.ranges.empty()) {
      throw std::runtime_error(model_.name + " " + port_ + ": scan telegram without frequency or geometry");
    }
    LaserScanData out;
    out.angle_min = t.start_angle * kTenThousandthDegree - M_PI / 2.0;  // SICK's 0 deg is the device's +y
    out.angle_increment = t.angular_step * kTenThousandthDegree;
    out.scan_time = 100.0 / t.scan_frequency;
    out.time_increment = t.measurement_frequency > 0 ? 1.0 / (100.0 * t.measurement_frequency) : 0.0;
    out.range_min = model_.range_min;  // the data sheet's: the telegram does not carry them
    out.range_max = model_.range_max;
    out.ranges.reserve(t.ranges.size());
    for (std::uint32_t value : t.ranges) {
      out.ranges.push_back(value == 0 ? std::numeric_limits<float>::infinity()
                                      : static_cast<float>((value * t.scale_factor + t.scale_offset) / 1000.0));
    }
    out.stamp = received - out.time_increment * static_cast<double>(t.ranges.size() - 1);
    *scan = std::move(out);
    return true;
  }

  std::string identity() const override { return identity_; }

 private:
  std::runtime_error failure(const std::string& what) const { return std::runtime_error(model_.name + " " + port_ + ": " + what); }

  std::string request(const std::string& body) {
    const std::string telegram = cola::frame(body);
    if (socket_.write(telegram.data(), telegram.size(), 1000) != telegram.size()) throw failure("write failed");
    std::string answer;
    if (!next(&answer, 2000)) throw failure("no answer to '" + body + "'");
    return answer;
  }

  void startLms() {
    if (request("sMN SetAccessMode 03 F4724744") != "sAN SetAccessMode 1") throw failure("login as authorised client refused");
    const std::string cfg = request("sRN LMPscancfg");
    const std::vector<std::string> f = fields(cfg);
    if (f.size() < 7 || f[1] != "LMPscancfg") throw failure("unexpected LMPscancfg reply '" + cfg + "'");
    try {
      const double hz = cola::parseHex(f[2], "scan frequency") / 100.0;
      const double step = cola::parseHex(f[4], "angular resolution") / 10000.0;
      const double start = static_cast<std::int32_t>(cola::parseHex(f[5], "start angle")) / 10000.0;
      const double stop = static_cast<std::int32_t>(cola::parseHex(f[6], "stop angle")) / 10000.0;
      std::ostringstream out;
      out << ", scan configuration " << hz << " Hz, " << step << " deg, " << start << " .. " << stop << " deg";
      identity_ += out.str();
    } catch (const std::invalid_argument& e) {
      throw failure(e.what());
    }
    if (request("sMN LMCstartmeas") != "sAN LMCstartmeas 0") throw failure("LMCstartmeas refused");
    if (request("sMN Run") != "sAN Run 1") throw failure("Run refused");
    for (int attempt = 0;; ++attempt) {  // the motor spins up: a few seconds on a real device
      const std::vector<std::string> status = fields(request("sRN STlms"));
      if (status.size() >= 3 && status[1] == "STlms" && status[2] == "7") return;
      if (attempt >= 100) throw failure("not ready for measurement after 10 s (STlms " + (status.size() >= 3 ? status[2] : "?") + ")");
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }

  // The next telegram within timeout_ms; throws when the connection is gone.
  bool next(std::string* body, int timeout_ms) {
    const double end = systemSeconds() + timeout_ms / 1000.0;
    while (!cola::nextTelegram(&buffer_, body)) {
      if (buffer_.size() > 1 << 20) throw failure("no ETX in 1 MiB");
      const int left = static_cast<int>((end - systemSeconds()) * 1000.0);
      if (left <= 0) return false;
      char chunk[8192];
      const std::size_t n = socket_.read(chunk, sizeof(chunk), left, 2);
      if (n == 0 && !socket_.isOpen()) throw failure("connection closed");
      buffer_.append(chunk, n);
    }
    return true;
  }

  std::string port_, identity_, buffer_;
  LaserModel model_;
  link::TcpClient socket_;
};

}  // namespace

std::unique_ptr<LaserDevice> openCola(const std::string& model, const std::string& port) {
  return std::make_unique<ColaDevice>(model, port);
}

}  // namespace sensors
}  // namespace amigobot_tracking
