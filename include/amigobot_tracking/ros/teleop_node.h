// What keyboard_teleop and joystick_teleop share: stopping on SIGINT/SIGTERM/SIGHUP with a
// last zero command (roscpp's own SIGINT handler would end ros::ok() before that zero could
// leave), and the optional call of the driver's enable_motors service.
#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace ros_layer {

// Installs handlers (without SA_RESTART, so a waiting poll() returns) that record the signal;
// use with ros::init_options::NoSigintHandler.
void installStopSignals();
// The signal that asked the node to stop, 0 while none did.
int stopSignal();

void publishCommand(const ros::Publisher& publisher, const core::Twist2& command);
// Publishes a zero command and gives roscpp up to `linger` seconds to deliver it to the
// subscribers before the node goes away.
void publishFinalZero(const ros::Publisher& publisher, double linger = 0.3);

// Calls the `enable_motors` service (std_srvs/Empty, the driver's, resolved in nh's
// namespace), waiting up to `timeout` s for it. False (and an error log) when it failed.
bool enableMotors(ros::NodeHandle& nh, const std::string& program, double timeout = 5.0);

}  // namespace ros_layer
}  // namespace amigobot_tracking
