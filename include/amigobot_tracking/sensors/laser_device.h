// One connection to a laser, opened by its model's driver: MRPT's CHokuyoURG for SCIP 2.0
// (serial or TCP), a CoLa-A client over link::TcpClient for the SICK TiM5xx and LMS1xx,
// a client of Slamtec's binary protocol over link::SerialPort for the RPLIDAR. A device
// reports scans with its own geometry and throws std::runtime_error once the link is broken;
// LaserDriver (laser_driver.h) then drops it and opens a new one.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace amigobot_tracking {
namespace sensors {

// One scan, REP 117 coded: +inf no echo within range, NaN an invalid measurement.
struct LaserScanData {
  double angle_min = 0.0, angle_increment = 0.0;  // [rad] the device's own beam angles
  double time_increment = 0.0, scan_time = 0.0;   // [s]
  double range_min = 0.0, range_max = 0.0;        // [m]
  std::vector<float> ranges;                      // [m]
  std::vector<float> intensities;                 // empty when the device sends none
  double stamp = 0.0;  // [s] system clock: when the first beam was measured
  std::uint64_t sequence = 0;

  double angleMax() const { return angle_min + angle_increment * (static_cast<double>(ranges.size()) - 1.0); }
};

// A scan that was damaged (malformed, truncated, bad checksum): skipped, the link stays.
struct ScanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class LaserDevice {
 public:
  virtual ~LaserDevice() = default;
  // Waits up to timeout_ms for one scan: true with it, false when none came yet. Throws
  // ScanError for a damaged scan, std::runtime_error once the link is broken.
  virtual bool read(LaserScanData* scan, int timeout_ms) = 0;
  virtual std::string identity() const = 0;  // model, firmware, serial as the device says
  // Stops (scanning and the motor) or restarts a device with a motor of its own (RPLIDAR:
  // rplidar_ros's stop_motor / start_motor); throws std::runtime_error once the link is broken.
  // The others always spin: nothing to do.
  virtual void setMotor(bool /*on*/) {}
};

// Each protocol's device is opened by its LaserProtocol::open (scip_protocol.h and the others
// declare theirs): it connects, configures and starts the measurement, or throws
// std::runtime_error naming the model and the port.

double systemSeconds();

}  // namespace sensors
}  // namespace amigobot_tracking
