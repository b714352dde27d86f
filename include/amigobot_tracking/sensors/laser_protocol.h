// One laser protocol behind one interface: everything that differs between SCIP 2.0, CoLa-A
// and Slamtec's RPLIDAR protocol (the driver's device, the emulator's session and faults,
// what the ROS node offers) is a virtual call or a property here, and the geometry its
// numbers give is its ProtocolGeometry (laser_model.h), so the driver, the emulator and the
// nodelet never branch on a protocol. A model's protocol and numbers are set once by its
// laser_registry.cpp entry. Adding a protocol: its own files (like scip_protocol.h/.cpp: the
// class, its numbers, its accessor) and one registry entry; this file names none of them
// (docs/architecture.md, "Adding a laser protocol").
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "amigobot_tracking/sensors/laser_device.h"
#include "amigobot_tracking/sensors/laser_model.h"
#include "amigobot_tracking/sensors/laser_session.h"

namespace amigobot_tracking {
namespace sensors {

class LaserProtocol {
 public:
  virtual ~LaserProtocol() = default;
  virtual std::string name() const = 0;  // "SCIP 2.0", for messages

  // Driver side: opens the device of laser_registry.h entry `model` at `port` (a serial
  // device or host:port; baud 0 or one of the entry's bauds), or throws naming both.
  virtual std::unique_ptr<LaserDevice> open(const std::string& model, const std::string& port, int baud) const = 0;

  // Emulator side: the session of one client connection.
  virtual std::unique_ptr<LaserSession> session(const LaserModel& model, const std::string& serial) const = 0;
  // The device code of a range without a measurement (r non-finite: +inf, -inf or NaN).
  virtual std::uint32_t noMeasurementCode(float r) const = 0;
  // A scan is one revolution of samples at the device's own, uneven angles, each sample
  // leaving as it is measured (RPLIDAR); false: a fixed grid sent once its last beam is measured.
  virtual bool samplesAsItTurns() const = 0;
  // With samplesAsItTurns: the device angles (REP 103) of one revolution's samples, from
  // *phase on (the protocol's own measure of where the next sample falls), leaving *phase
  // where the next revolution starts; `random` draws what varies from one revolution to the
  // next. The emulator's ScanSource casts a ray along each.
  virtual std::vector<double> revolutionAngles(const LaserModel& model, double* /*phase*/, std::mt19937& /*random*/) const {
    throw std::logic_error("laser model '" + model.name + "': " + name() + " sends a fixed grid, not samples as it turns");
  }
  // The emulator's faults on a streamed scan telegram: a malformed one (still framed, its
  // content not parseable), and for a protocol with a checksum, one with a wrong sum.
  virtual std::string malformed(std::string telegram) const = 0;
  virtual bool hasChecksum() const = 0;
  virtual std::string badChecksum(std::string telegram) const { return telegram; }

  // ROS side: the device has a motor the host starts and stops (rplidar_ros's start_motor
  // and stop_motor services).
  virtual bool hasMotor() const = 0;
  // The angle convention of this protocol's ROS driver that the nodelet may imitate besides
  // the device's own ("rplidar_ros": pi - theta); empty: none.
  virtual std::string rosDriverAngleConvention() const { return ""; }
};

// Position just after the n-th `c` in `text`, or npos: where a fault damages a telegram.
std::size_t afterNth(const std::string& text, char c, int n);

}  // namespace sensors
}  // namespace amigobot_tracking
