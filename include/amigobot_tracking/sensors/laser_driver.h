// The ROS-free laser driver: opens the device of its model, hands out its scans, and after a
// broken link or a stall reopens it with exponential back-off (reconnect_period, doubling up
// to 8 times that). Not thread-safe: one I/O thread calls poll().
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include "amigobot_tracking/sensors/laser_device.h"

namespace amigobot_tracking {
namespace sensors {

struct LaserDriverConfig {
  std::string model = "hokuyo_urg";    // an entry of laser_registry.h
  std::string port = "/dev/ttyACM0";   // serial device, host:port, or laser_emulator:PORT (laser_registry.h)
  double reconnect_period = 1.0;       // [s] first wait before reopening
  double stall_timeout = 1.0;          // [s] no scan for this long: the link is reopened
  int baud = 0;                        // one of the model's bauds (rplidar: 115200 or 256000); 0: its first

  // Checks laserDriverFields() (laser_registry.h) and the model's link and bauds; throws
  // std::invalid_argument naming the bad field.
  void validate() const;
};

struct LaserDriverCounters {
  std::uint64_t scans = 0, damaged = 0, link_failures = 0, stalls = 0, opens = 0;
};

class LaserDriver {
 public:
  explicit LaserDriver(LaserDriverConfig config);
  // Opens the device when due and waits up to timeout [s] for one scan. True with a new
  // scan; false otherwise (lastError() says why, empty when the scan simply is not due).
  bool poll(LaserScanData* scan, double timeout);
  bool connected() const { return device_ != nullptr; }
  // The motor stopped or running (rplidar_ros's stop_motor / start_motor): callable from any
  // thread; poll() applies it, also to a device it reopens. While stopped no scan comes, and
  // that is no stall.
  void requestMotor(bool on) { motor_wanted_ = on; }
  bool motorRunning() const { return motor_wanted_; }
  std::string identity() const { return identity_; }
  const std::string& lastError() const { return last_error_; }
  const LaserDriverCounters& counters() const { return counters_; }
  void close();

 private:
  void fail(const std::string& why);

  LaserDriverConfig config_;
  std::unique_ptr<LaserDevice> device_;
  std::string identity_, last_error_;
  LaserDriverCounters counters_;
  double next_open_ = 0.0, backoff_ = 0.0, last_scan_ = 0.0;
  std::uint64_t sequence_ = 0;
  std::atomic<bool> motor_wanted_{true};
  bool motor_on_ = true;  // as the open device was last told (a device opens spinning)
};

}  // namespace sensors
}  // namespace amigobot_tracking
