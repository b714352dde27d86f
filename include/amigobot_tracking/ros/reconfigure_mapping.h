// dynamic_reconfigure <-> ControllerConfig, by field name through the controller's table
// (core::controllerFields(), the live rows): cfg/Tracking.cfg names the fields, nothing else
// lists them.
#pragma once

#include <string>

#include "amigobot_tracking/TrackingConfig.h"
#include "amigobot_tracking/core/controller_config.h"

namespace amigobot_tracking {
namespace ros_layer {

// Sets every field named by an entry of `config` on *controller (no bounds check: the caller
// validates). "" or "reconfigure entry 'x' is no live controller field".
std::string applyReconfigure(const TrackingConfig& config, core::ControllerConfig* controller);
// Writes the controller's values into the entries of *config (same names).
std::string fillReconfigure(const core::ControllerConfig& controller, TrackingConfig* config);
// "k_d 0.15, k_o 1, ..." over the live fields, for the log.
std::string describeLiveFields(const core::ControllerConfig& controller);

}  // namespace ros_layer
}  // namespace amigobot_tracking
