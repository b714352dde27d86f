// The one list of the lasers the package knows: one entry per model with everything that
// differs from one model to the next (its name, protocol, link, serial speeds, geometry and
// data-sheet limits, how the driver opens it, how the emulator answers for it). The driver,
// the emulator, the Laser nodelet's parameters and the tools read it; adding a model is one
// entry here plus its protocol files. A name not in the list is an error everywhere,
// naming it and the known ones.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "amigobot_tracking/core/field_table.h"
#include "amigobot_tracking/sensors/laser_device.h"
#include "amigobot_tracking/sensors/laser_driver.h"
#include "amigobot_tracking/sensors/laser_model.h"
#include "amigobot_tracking/sensors/laser_session.h"

namespace amigobot_tracking {
namespace sensors {

enum class LaserLink { kSerial, kTcp, kSerialOrTcp };

struct LaserModelEntry {
  std::string name;         // the `model` parameter's value
  std::string description;  // the device and its data sheet's figures
  LaserLink link = LaserLink::kSerialOrTcp;
  std::vector<int> bauds;   // serial speeds the driver may choose, the first the default; empty: the device's own
  std::function<LaserModel()> model;  // geometry, rate, range limits
  std::function<std::unique_ptr<LaserDevice>(const std::string& port, int baud)> open;  // baud: 0 or one of `bauds`
  std::function<std::unique_ptr<LaserSession>(const LaserModel& model, const std::string& serial)> session;

  bool tcp() const { return link != LaserLink::kSerial; }
  bool serial() const { return link != LaserLink::kTcp; }
};

const std::vector<LaserModelEntry>& laserModels();
// The entry of `name`; throws std::invalid_argument "model: 'NAME' is not a known laser (...)".
const LaserModelEntry& laserModelEntry(const std::string& name);
std::vector<std::string> laserModelNames();
std::string laserModelList();  // "hokuyo_urg | sick_tim5xx | ...", for help texts and errors

// The driver's settings, described once (bounds, units, the model's choices from the list
// above): LaserDriverConfig::validate and the Laser nodelet's parameters both walk it.
const core::FieldTable<LaserDriverConfig>& laserDriverFields();

}  // namespace sensors
}  // namespace amigobot_tracking
