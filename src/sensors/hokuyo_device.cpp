// SCIP 2.0 through MRPT's CHokuyoURG. MRPT spreads the N beams evenly over its aperture;
// the beam angles here come from the PP reply instead: (step - AFRT) 2 pi / ARES.
// MRPT drops each line's sum character unchecked, so the link is bound to CHokuyoURG as a
// stream that checks the sums of what MRPT reads (scip::ReplySumCheck): a scan read while a
// wrong sum went by is dropped as damaged. Over TCP that stream is link::TcpClient, not MRPT's socket class,
// so CHokuyoURG treats it as an already open port and leaves reconnecting to LaserDriver.
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <mrpt/comms/CSerialPort.h>
#include <mrpt/hwdrivers/CHokuyoURG.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "amigobot_tracking/core/support/error_text.h"
#include "amigobot_tracking/link/address.h"
#include "amigobot_tracking/link/tcp_client.h"
#include "amigobot_tracking/sensors/laser_device.h"
#include "amigobot_tracking/sensors/scip.h"
#include "amigobot_tracking/sensors/scip_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

// A serial port that checks the SCIP sums of what it reads (CHokuyoURG still sets its baud).
class SumCheckedSerialPort : public mrpt::comms::CSerialPort {
 public:
  SumCheckedSerialPort(const std::string& port, scip::ReplySumCheck* check) : CSerialPort(port, true), check_(check) {}
  size_t Read(void* buffer, size_t count) override {
    const size_t n = CSerialPort::Read(buffer, count);
    check_->feed(static_cast<const char*>(buffer), n);
    return n;
  }

 private:
  scip::ReplySumCheck* check_;
};

// A TCP connection as a plain stream that checks the SCIP sums of what it reads. Read waits
// up to 100 ms for the first byte, as CHokuyoURG's serial timeouts do.
class SumCheckedSocket : public mrpt::io::CStream {
 public:
  SumCheckedSocket(const link::TcpAddress& address, scip::ReplySumCheck* check) : check_(check) {
    socket_.connect(address, 2000);
  }
  size_t Read(void* buffer, size_t count) override {
    if (!socket_.isOpen()) throw std::runtime_error("connection closed");
    const size_t n = socket_.read(buffer, count, 100, 1);
    check_->feed(static_cast<const char*>(buffer), n);
    return n;
  }
  size_t Write(const void* buffer, size_t count) override { return socket_.write(buffer, count, 1000); }
  uint64_t Seek(int64_t, CStream::TSeekOrigin) override { throw std::logic_error("SumCheckedSocket: no seek"); }
  uint64_t getTotalBytesCount() const override { return 0; }
  uint64_t getPosition() const override { return 0; }

 private:
  link::TcpClient socket_;
  scip::ReplySumCheck* check_;
};

// CHokuyoURG keeps the PP reply in a protected member: read it from a subclass.
class Urg : public mrpt::hwdrivers::CHokuyoURG {
 public:
  const TSensorInfo& info() const { return m_sensor_info; }
  // Reception time, not MRPT's firmware-clock fit (which drifts from the first packets).
  void useReceptionTime() { m_disable_firmware_timestamp = true; }
};

class HokuyoDevice : public LaserDevice {
 public:
  HokuyoDevice(const std::string& model, const std::string& port) : port_(port), where_(model + " " + port) {
    urg_.setMinLoggingLevel(mrpt::system::LVL_ERROR);
    urg_.useReceptionTime();
    bool ok = false;
    try {
      if (const std::optional<link::TcpAddress> tcp = link::parseTcpAddress(port)) {
        urg_.bindIO(std::make_shared<SumCheckedSocket>(*tcp, &sums_));
      } else {
        urg_.setSerialPort(port);
        urg_.bindIO(std::make_shared<SumCheckedSerialPort>(port, &sums_));
      }
      ok = urg_.turnOn();
    } catch (const std::exception& e) {
      throw std::runtime_error(where_ + ": cannot open: " + core::libraryMessage(e.what()));
    }
    const auto& i = urg_.info();
    if (!ok || i.scans_per_360deg <= 0 || i.scan_last < i.scan_first) {
      throw std::runtime_error(where_ + ": no SCIP 2.0 answer (PP) from the device");
    }
    const double step = 2.0 * M_PI / i.scans_per_360deg;
    geometry_.angle_min = (i.scan_first - i.scan_front) * step;
    geometry_.angle_increment = step;
    geometry_.scan_time = i.motor_speed_rpm > 0 ? 60.0 / i.motor_speed_rpm : 0.1;
    geometry_.time_increment = geometry_.scan_time / i.scans_per_360deg;
    geometry_.range_min = i.d_min;
    geometry_.range_max = i.d_max;
    identity_ = "Hokuyo " + i.model + " (SCIP 2.0, ARES " + std::to_string(i.scans_per_360deg) + ", AMIN " +
                std::to_string(i.scan_first) + ", AMAX " + std::to_string(i.scan_last) + ", AFRT " +
                std::to_string(i.scan_front) + ") at " + port;
  }

  bool read(LaserScanData* scan, int /*timeout_ms: MRPT waits its comms timeout*/) override {
    bool have = false, error = false;
    mrpt::obs::CObservation2DRangeScan obs;
    urg_.doProcessSimple(have, obs, error);
    if (sums_.badLines() > bad_lines_) {
      bad_lines_ = sums_.badLines();
      throw ScanError(where_ + ": SCIP checksum wrong in line '" + sums_.lastBad().substr(0, 70) + "'");
    }
    // MRPT does not tell a damaged reply from a lost link: the driver reopens after a stall.
    if (error && !have) throw ScanError(where_ + ": damaged reply, device error or link lost");
    if (!have) return false;
    const double received = systemSeconds();
    const std::size_t n = obs.getScanSize();
    const std::size_t expected = static_cast<std::size_t>(urg_.info().scan_last - urg_.info().scan_first + 1);
    if (n != expected) throw ScanError(where_ + ": scan of " + std::to_string(n) + " beams");
    LaserScanData out = geometry_;
    out.ranges.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const float r = obs.getScanRange(k);
      // Values below DMIN are error codes: 0 no echo (REP 117: +inf), others invalid (NaN).
      if (obs.getScanRangeValidity(k)) {
        out.ranges[k] = r;
      } else {
        out.ranges[k] = std::lround(r * 1000.0f) == 0 ? std::numeric_limits<float>::infinity()
                                                      : std::numeric_limits<float>::quiet_NaN();
      }
    }
    // A URG sends a scan once its last beam is measured.
    out.stamp = received - out.time_increment * static_cast<double>(n - 1);
    *scan = std::move(out);
    return true;
  }

  std::string identity() const override { return identity_; }

 private:
  std::string port_, where_, identity_;  // where_: "MODEL PORT", for errors
  scip::ReplySumCheck sums_;  // before urg_: the streams bound to it point here
  std::uint64_t bad_lines_ = 0;
  Urg urg_;
  LaserScanData geometry_;
};

}  // namespace

std::unique_ptr<LaserDevice> openHokuyo(const std::string& model, const std::string& port) {
  return std::make_unique<HokuyoDevice>(model, port);
}

}  // namespace sensors
}  // namespace amigobot_tracking
