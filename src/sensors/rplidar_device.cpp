// Slamtec RPLIDAR A1/A2/A3 over a serial port (115200 8N1; A2M12/A3: 256000), a client of its own binary protocol
// (rplidar.h). Not MRPT's CRoboPeakLidar: it floors each sample's angle to a whole degree,
// keeps the last sample of each degree, and hands the 360 bins on as an MRPT scan spread
// evenly over 2 pi (360 beams, 359 intervals), so the device's angles are lost; its SDK's
// health, info and sample-rate replies are not passed on either.
//
// The RPLIDAR's angles are uneven and change from one revolution to the next: the scan is
// published on a fixed grid (RplidarGeometry::bins over [-pi, pi), each bin the sample
// nearest its centre, +inf where none fell). The revolution is stamped when its first node
// arrived; the samples are not in angle order in time (clockwise, from the front), so
// time_increment is 0 and scan_time the measured revolution period.
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "amigobot_tracking/link/serial_port.h"
#include "amigobot_tracking/sensors/laser_device.h"
#include "amigobot_tracking/sensors/laser_model.h"
#include "amigobot_tracking/sensors/rplidar.h"
#include "amigobot_tracking/sensors/rplidar_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

class RplidarDevice : public LaserDevice {
 public:
  RplidarDevice(const std::string& port, int baud) : port_(port), model_(laserModel("rplidar")) {
    // LaserDriverConfig::validate allows 115200 and 256000 only.
    try {
      serial_.open(port, baud);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("rplidar: ") + e.what());
    }
    fd_ = serial_.fd();
    // The A1/A2 USB adapters stop the motor while DTR is set (a pty has no modem lines).
    int dtr = TIOCM_DTR;
    ::ioctl(fd_, TIOCMBIC, &dtr);
    write(rplidar::request(rplidar::kStop));  // a scan left running by the last client
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    discardInput();
    const rplidar::Health health = rplidar::decodeHealth(reply(rplidar::kGetHealth, rplidar::kHealthType, rplidar::kHealthSize));
    if (health.status == 2) {
      write(rplidar::request(rplidar::kReset));
      throw failure("device reports a health error (code " + std::to_string(health.error_code) + "): reset sent");
    }
    const rplidar::Info info = rplidar::decodeInfo(reply(rplidar::kGetInfo, rplidar::kInfoType, rplidar::kInfoSize));
    const std::string rate = reply(rplidar::kGetSampleRate, rplidar::kSampleRateType, rplidar::kSampleRateSize);
    const int standard_us = static_cast<std::uint8_t>(rate[0]) | (static_cast<std::uint8_t>(rate[1]) << 8);
    std::ostringstream id;
    id << "Slamtec RPLIDAR model " << int(info.model) << ", firmware " << int(info.firmware_major) << "." << std::setw(2)
       << std::setfill('0') << int(info.firmware_minor) << ", hardware " << int(info.hardware) << ", serial ";
    for (std::uint8_t c : info.serial) id << std::hex << std::uppercase << std::setw(2) << int(c);
    id << std::dec << ", " << standard_us << " us per sample";
    if (health.status == 1) id << ", health warning " << health.error_code;
    identity_ = id.str() + " at " + port;
    startScan();
  }

  ~RplidarDevice() override {
    if (fd_ < 0) return;
    const std::string stop = rplidar::request(rplidar::kStop);
    (void)!::write(fd_, stop.data(), stop.size());
  }

  bool read(LaserScanData* scan, int timeout_ms) override {
    const double end = systemSeconds() + timeout_ms / 1000.0;
    for (;;) {
      while (buffer_.size() >= rplidar::kNodeSize) {
        rplidar::Node node;
        const std::string bad = rplidar::decodeNode(reinterpret_cast<const std::uint8_t*>(buffer_.data()), &node);
        if (!bad.empty()) {  // out of step: drop one byte and look again
          buffer_.erase(0, 1);
          damage_ = bad;
          continue;
        }
        buffer_.erase(0, rplidar::kNodeSize);
        if (node.start && started_ > 0.0) {
          const std::string why = incomplete();
          const bool have = why.empty() && take(scan);
          accept(node);
          if (have) return true;
          if (!why.empty()) throw ScanError("rplidar " + port_ + ": revolution dropped: " + why);
          continue;
        }
        accept(node);
      }
      const int left = static_cast<int>((end - systemSeconds()) * 1000.0);
      if (left <= 0) return false;
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, left);
      if (ready < 0 && errno != EINTR) throw failure(std::string("poll: ") + std::strerror(errno));
      if (ready <= 0) continue;
      if (p.revents & (POLLHUP | POLLERR | POLLNVAL)) throw failure("port closed");
      char chunk[4096];
      const ssize_t n = ::read(fd_, chunk, sizeof(chunk));
      if (n < 0 && errno != EAGAIN && errno != EINTR) throw failure(std::string("read: ") + std::strerror(errno));
      if (n > 0) buffer_.append(chunk, static_cast<std::size_t>(n));
    }
  }

  std::string identity() const override { return identity_; }

  void setMotor(bool on) override {
    int dtr = TIOCM_DTR;  // the A1/A2 USB adapter's motor line (no effect on a pty)
    if (!on) {
      write(rplidar::request(rplidar::kStop));
      write(rplidar::request(rplidar::kSetMotorPwm, std::string{0, 0}));
      ::ioctl(fd_, TIOCMBIS, &dtr);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      discardInput();
      buffer_.clear();  // the next revolution starts afresh
      samples_.clear();
      damage_.clear();
      started_ = 0.0;
      return;
    }
    ::ioctl(fd_, TIOCMBIC, &dtr);
    startScan();
  }

 private:
  // The motor at its default duty (a device stopped by the last client stays stopped), then SCAN.
  void startScan() {
    const std::uint16_t pwm = rplidar::kDefaultMotorPwm;
    write(rplidar::request(rplidar::kSetMotorPwm, std::string{static_cast<char>(pwm & 0xFF), static_cast<char>(pwm >> 8)}));
    write(rplidar::request(rplidar::kScan));
    // Nodes the device sent before it took a STOP may still arrive: skipped up to the descriptor.
    std::string window = readExactly(rplidar::kDescriptorSize, 2000);
    for (const double end = systemSeconds() + 2.0;;) {
      rplidar::Descriptor d;
      const std::string error = rplidar::decodeDescriptor(window, &d);
      if (error.empty() && d.type == rplidar::kMeasurementType && d.multiple && d.length == rplidar::kNodeSize) return;
      if (systemSeconds() > end) throw failure("SCAN not acknowledged: " + (error.empty() ? "unexpected descriptor" : error));
      window = window.substr(1) + readExactly(1, 2000);
    }
  }

  std::runtime_error failure(const std::string& what) const { return std::runtime_error("rplidar " + port_ + ": " + what); }

  void write(const std::string& bytes) {
    if (::write(fd_, bytes.data(), bytes.size()) != static_cast<ssize_t>(bytes.size())) throw failure("write failed");
  }

  void discardInput() { serial_.discardInput(); }

  std::string readExactly(std::size_t count, int timeout_ms) {
    const double end = systemSeconds() + timeout_ms / 1000.0;
    std::string out;
    while (out.size() < count) {
      const int left = static_cast<int>((end - systemSeconds()) * 1000.0);
      pollfd p{fd_, POLLIN, 0};
      if (left <= 0 || ::poll(&p, 1, left) <= 0) throw failure("no answer within " + std::to_string(timeout_ms) + " ms");
      char chunk[64];
      const ssize_t n = ::read(fd_, chunk, std::min(sizeof(chunk), count - out.size()));
      if (n > 0) out.append(chunk, static_cast<std::size_t>(n));
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) throw failure("port closed");
    }
    return out;
  }

  // Sends `command` and returns its data after checking the descriptor.
  std::string reply(rplidar::Command command, rplidar::DataType type, std::size_t size) {
    write(rplidar::request(command));
    rplidar::Descriptor d;
    const std::string error = rplidar::decodeDescriptor(readExactly(rplidar::kDescriptorSize, 1000), &d);
    if (!error.empty()) throw failure("answer to command 0x" + hexByte(command) + ": " + error);
    if (d.type != type || d.length < size) throw failure("answer to command 0x" + hexByte(command) + " of type 0x" + hexByte(d.type));
    return readExactly(d.length, 1000).substr(0, size);
  }

  static std::string hexByte(int value) {
    std::ostringstream out;
    out << std::hex << std::uppercase << std::setw(2) << std::setfill('0') << value;
    return out.str();
  }

  // Why the revolution just ended cannot be published (damaged bytes, nodes missing at its
  // end), or empty.
  std::string incomplete() {
    std::string why = damage_;
    damage_.clear();
    const int last_q6 = samples_.empty() ? 0 : rplidar::angleQ6(samples_.back().angle);
    if (why.empty() && last_q6 < 355 * 64) why = "it ends at " + std::to_string(last_q6 / 64) + " deg";
    return why;
  }

  void accept(const rplidar::Node& node) {
    if (node.start) {
      started_ = systemSeconds();
      samples_.clear();
    }
    if (started_ <= 0.0) return;  // before the first revolution start: a partial one
    const float range = node.distance_q2 == 0 ? std::numeric_limits<float>::infinity()
                                              : static_cast<float>(node.distance_q2 / 4000.0);
    samples_.push_back({rplidar::nodeAngle(node.angle_q6), range});
  }

  // The finished revolution (before a start node) as a scan.
  bool take(LaserScanData* scan) {
    LaserScanData out;
    out.angle_min = model_.angleMin();
    out.angle_increment = model_.angleIncrement();
    out.scan_time = systemSeconds() - started_;  // from its start node to the next one
    out.time_increment = 0.0;
    out.range_min = model_.range_min;
    out.range_max = model_.range_max;
    out.ranges = rplidar::binRevolution(samples_, model_.protocolGeometry<RplidarGeometry>().bins);
    out.stamp = started_;
    *scan = std::move(out);
    return true;
  }

  std::string port_, identity_, buffer_, damage_;
  LaserModel model_;
  link::SerialPort serial_;  // raw 8N1 at 115200 or 256000
  int fd_ = -1;              // serial_'s, read with poll() here
  std::vector<rplidar::Sample> samples_;
  double started_ = 0.0;  // [s] when the first node of this revolution arrived
};

}  // namespace

std::unique_ptr<LaserDevice> openRplidar(const std::string& port, int baud) {
  return std::make_unique<RplidarDevice>(port, baud);
}

}  // namespace sensors
}  // namespace amigobot_tracking
