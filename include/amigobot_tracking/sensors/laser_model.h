// The lasers the emulator imitates and the driver knows: their geometry in the sensor frame
// (REP 103: x forward, angles counter-clockwise), rate and range, and the protocol numbers
// behind that geometry. The numbers are each protocol's own, declared with it (ScipGeometry
// in scip_protocol.h, and so for each); a model holds them behind ProtocolGeometry, so this
// file names no protocol and a new protocol does not edit it.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "amigobot_tracking/core/perception/scan_obstacles.h"

namespace amigobot_tracking {
namespace sensors {

class LaserProtocol;  // laser_protocol.h

// A protocol's numbers for one model (what the device reports of itself: SCIP's PP, CoLa-A's
// scan telegram, RPLIDAR's sample rate) and the beams and device angles (REP 103) they give.
// Only the protocol's own files read the numbers (LaserModel::protocolGeometry<G>()).
class ProtocolGeometry {
 public:
  virtual ~ProtocolGeometry() = default;
  virtual int beams() const = 0;
  virtual double angleMin() const = 0;
  virtual double angleIncrement() const = 0;
};

struct LaserModel {
  std::string name;  // its entry in laser_registry.h
  const LaserProtocol* protocol = nullptr;  // set by its registry entry; never owned
  // Set by its registry entry with the protocol; shared and never changed in place, so a copy
  // of the model is a value (setProtocolGeometry replaces it).
  std::shared_ptr<const ProtocolGeometry> protocol_geometry;
  double range_min = 0.02, range_max = 4.0;  // [m]
  double rate = 10.0;                        // [Hz] scans per second

  // From the protocol's numbers; throws std::logic_error without a protocol or its numbers.
  int beams() const;
  double angleMin() const;
  double angleIncrement() const;
  double angleMax() const { return angleMin() + angleIncrement() * (beams() - 1); }
  double scanTime() const { return 1.0 / rate; }
  // Time between beams: one revolution (a full turn of the mirror) takes scanTime().
  double timeIncrement() const;
  core::ScanGeometry geometry() const;

  // The protocol's numbers as its own type G (G::kName names it); throws std::logic_error
  // naming the model when it holds none or another protocol's: a model/protocol mismatch is
  // a programming error, never a user's.
  template <class G>
  const G& protocolGeometry() const {
    const G* g = dynamic_cast<const G*>(protocol_geometry.get());
    if (!g) throw std::logic_error("laser model '" + name + "': no " + G::kName + " numbers (its protocol's are another's)");
    return *g;
  }
  template <class G>
  void setProtocolGeometry(G geometry) {
    protocol_geometry = std::make_shared<const G>(std::move(geometry));
  }
};

// The model's protocol; throws std::logic_error for a model built without its registry entry.
const LaserProtocol& protocolOf(const LaserModel& model);
// The model's numbers, as any protocol's; throws std::logic_error as protocolOf, or naming the
// model when it has a protocol but no numbers.
const ProtocolGeometry& protocolGeometryOf(const LaserModel& model);
// The model of a laser_registry.h entry (laser_registry.cpp); throws std::invalid_argument
// naming `name` and the known models when there is no such entry.
LaserModel laserModel(const std::string& name);

}  // namespace sensors
}  // namespace amigobot_tracking
