// The sensor side of one client connection of the laser emulator: parses the client's
// requests and answers as the device would (SCIP 2.0 for hokuyo_urg, CoLa-A for
// sick_tim5xx and sick_lms1xx, Slamtec's binary protocol for rplidar), and streams scans
// once the client has asked for them. No I/O: the server
// moves the bytes, which keeps the protocol logic testable.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "amigobot_tracking/sensors/laser_model.h"

namespace amigobot_tracking {
namespace sensors {

// One scan in metres, REP 117 coded: +inf nothing within range, -inf closer than range_min,
// NaN a dropout. `t` [s] is the emulator's clock when the first beam was measured.
struct EmulatedScan {
  std::vector<float> ranges;
  std::vector<float> angles;  // [rad] sensor frame, one per range (RPLIDAR); empty: the model's grid
  double t = 0.0;
  std::uint64_t index = 0;
};

// Device-coded ranges. SCIP: millimetres, error code 0 for no echo within DMAX and 1 for a
// dropout or a too-close beam (the URG reports values below DMIN as error codes).
// CoLa-A: millimetres, 0 for every beam without a measurement.
std::vector<std::uint32_t> deviceRanges(const LaserModel& model, const std::vector<float>& ranges);

class LaserSession {
 public:
  virtual ~LaserSession() = default;
  // Bytes from the client -> the replies (the latest scan answers a single-scan request).
  virtual std::string receive(const std::string& bytes, const EmulatedScan& latest) = 0;
  // The telegram to stream for a new scan; empty while the client has not asked for scans.
  virtual std::string stream(const EmulatedScan& scan) = 0;
  // Requests seen so far (the tests check the driver's conversation).
  const std::vector<std::string>& requests() const { return requests_; }

 protected:
  std::vector<std::string> requests_;
};

// The session of the model's protocol (laser_protocol.h); throws naming a model that is not
// in the registry (laser_registry.h).
std::unique_ptr<LaserSession> makeSession(const LaserModel& model, const std::string& serial);

}  // namespace sensors
}  // namespace amigobot_tracking
