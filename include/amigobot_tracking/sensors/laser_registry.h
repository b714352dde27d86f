// The one list of the lasers the package knows: one entry per model with everything that
// differs from one model to the next (its name, link, serial speeds, geometry and data-sheet
// limits, and its protocol (laser_protocol.h): how the driver opens it, how the emulator
// answers for it). The driver, the emulator, the Laser nodelet's parameters and the tools
// read it; adding a model is one entry here, adding a protocol its own files besides. A name not in the list is an error everywhere,
// naming it and the known ones.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/sensors/laser_device.h"
#include "amigobot_tracking/sensors/laser_driver.h"
#include "amigobot_tracking/sensors/laser_model.h"
#include "amigobot_tracking/sensors/laser_session.h"

namespace amigobot_tracking {
namespace sensors {

enum class LaserLink { kSerial, kTcp, kSerialOrTcp };

// A device whose scan is chosen at start-up (frequency, angular resolution), as the LMS1xx's
// mLMPsetscancfg: the emulator's --scan-frequency / --resolution. A fixed-scan model has none.
struct LaserScanSetting {
  std::string choices;  // the data sheet's pairs, for help texts
  double frequency_hz = 0.0, resolution_deg = 0.0;  // the entry's model's own scan
  std::function<void(LaserModel*, double frequency_hz, double resolution_deg)> apply;  // throws naming a bad value
};

struct LaserModelEntry {
  std::string name;         // the `model` parameter's value
  std::string description;  // the device and its data sheet's figures
  LaserLink link = LaserLink::kSerialOrTcp;
  std::vector<int> bauds;   // serial speeds the driver may choose, the first the default; empty: the device's own
  std::function<LaserModel()> model;  // protocol, geometry, rate, range limits
  std::optional<LaserScanSetting> scan_setting;  // empty: the scan is fixed

  bool tcp() const { return link != LaserLink::kSerial; }
  bool serial() const { return link != LaserLink::kTcp; }
  // The driver's device: the model's protocol opens it (baud: 0 or one of `bauds`).
  std::unique_ptr<LaserDevice> open(const std::string& port, int baud) const;
};

const std::vector<LaserModelEntry>& laserModels();
// The entry of `name`; throws std::invalid_argument "model: 'NAME' is not a known laser (...)".
const LaserModelEntry& laserModelEntry(const std::string& name);
std::vector<std::string> laserModelNames();
std::string laserModelList();  // "hokuyo_urg | sick_tim5xx | ...", for help texts and errors

// Where laser_emulator --endpoint PORT serves a model, and so where the driver finds it: by
// the entry's link, so a launch file passes the port alone and no caller compares names. A
// serial-only model gets a pseudo-terminal linked at /tmp/amigobot_laser_MODEL_PORT (PORT
// keeps two emulators apart), any other TCP on localhost:PORT.
struct LaserEndpoint {
  int tcp_port = -1;  // -1: none
  std::string pty;    // empty: none
  std::string address() const;  // what the driver opens: the pty, or localhost:PORT
};
// Throws std::invalid_argument for an unknown model (as laserModelEntry) or a port outside 1..65535.
LaserEndpoint laserEmulatorEndpoint(const std::string& model, int port);
// The driver's `port` parameter may name that endpoint as "laser_emulator:PORT" (no host
// name holds '_', so no real host:port reads so); anything else is returned as it is.
std::string resolveLaserPort(const std::string& model, const std::string& port);

// The driver's settings, described once (bounds, units, the model's choices from the list
// above): LaserDriverConfig::validate and the Laser nodelet's parameters both walk it.
const core::FieldTable<LaserDriverConfig>& laserDriverFields();

}  // namespace sensors
}  // namespace amigobot_tracking
