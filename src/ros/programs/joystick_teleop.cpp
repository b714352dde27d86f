// joystick_teleop: drives a robot from a Linux joystick (/dev/input/jsN, linux/joystick.h's
// struct js_event API) without the joy package, which Debian 12 does not ship: cmd_vel
// (geometry_msgs/Twist) at `rate` while the deadman button is held, one zero when it is
// released, when the device disappears (then reopened every reconnect_period), when it has
// been silent for stale_timeout (if set) and on exit. Mapping: teleop/joystick.h.
#include <algorithm>
#include <cstdio>
#include <thread>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include "amigobot_tracking/ros/node_command_line.h"
#include "amigobot_tracking/ros/param_reader.h"
#include "amigobot_tracking/ros/teleop_node.h"
#include "amigobot_tracking/teleop/joystick.h"
#include "amigobot_tracking/teleop/joystick_device.h"

using namespace amigobot_tracking;

const ros_layer::NodeHelp kHelp{
    "Joystick tele-operation from a Linux joystick device (struct js_event API): publishes cmd_vel "
    "(geometry_msgs/Twist) at `rate` while the deadman button is held: v = scale_linear x axis_linear, "
    "omega = scale_angular x axis_angular (stick up/left positive; the turbo scales while turbo_button "
    "is held); one zero on release, on device loss (reopened every reconnect_period) and on exit.",
    "device, axis_linear, axis_angular, scale_linear, scale_angular, deadman_button, turbo_button, "
    "scale_linear_turbo, scale_angular_turbo, deadzone, rate, stale_timeout, reconnect_period, "
    "enable_motors: config/teleop.yaml (include/amigobot_tracking/teleop/joystick.h)."};

namespace {

double now() { return ros::WallTime::now().toSec(); }

// One error line per new problem; the same problem again at most every 10 s.
void reportProblem(const std::string& problem, std::string* last) {
  if (problem != *last) ROS_ERROR_STREAM("joystick_teleop: " << problem);
  else ROS_ERROR_STREAM_THROTTLE(10.0, "joystick_teleop: " << problem << " (still)");
  *last = problem;
}

}  // namespace

int main(int argc, char** argv) {
  ros_layer::initNode(argc, argv, "joystick_teleop", kHelp, ros::init_options::NoSigintHandler);
  ros_layer::installStopSignals();
  ros::NodeHandle nh, pnh("~");
  teleop::JoystickConfig config;
  if (!ros_layer::configLoaded("joystick_teleop", ros_layer::readParams(pnh, teleop::joystickFields(), &config)))
    return 1;
  ros::Publisher publisher = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  if (config.enable_motors) ros_layer::enableMotors(nh, "joystick_teleop");

  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // log lines reach a pipe or a file at once
  const std::string retry = core::formatValue(config.reconnect_period);
  teleop::JoystickDevice device(config.device);
  teleop::JoystickTeleop joystick(config);
  const double period = 1.0 / config.rate;
  double next_tick = now(), next_open = now();
  bool connected = false, was_stale = false;
  std::string last_problem, bytes;
  std::vector<teleop::JoystickEvent> events;
  while (ros::ok() && ros_layer::stopSignal() == 0) {
    if (!device.isOpen() && now() >= next_open) {
      const std::string problem = device.open();
      if (!problem.empty()) reportProblem(problem + "; retrying every " + retry + " s", &last_problem);
      next_open = now() + config.reconnect_period;
    }
    const int wait_ms = static_cast<int>(std::max(0.0, next_tick - now()) * 1000.0);
    if (device.isOpen()) {
      const std::string problem = device.read(wait_ms, &bytes);
      if (!problem.empty()) {
        joystick.onDeviceLost();
        bytes.clear();
        if (connected) ROS_ERROR_STREAM("joystick_teleop: " << problem << "; zero sent, reopening every " << retry << " s");
        else reportProblem(problem, &last_problem);
        last_problem = problem;
        connected = false;
        next_open = now() + config.reconnect_period;
      }
      events.clear();
      teleop::decodeEvents(&bytes, &events);
      if (!events.empty() && !connected) {
        const std::string what = device.describe();
        ROS_INFO_STREAM("joystick_teleop: device " << config.device << ": connected" << (what.empty() ? "" : " (" + what + ")")
                                                   << "; hold button " << config.deadman_button << " to drive");
        connected = true;
        last_problem.clear();
      }
      const double t = now();
      for (const teleop::JoystickEvent& e : events) joystick.onEvent(e, t);
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
    }
    const double t = now();
    if (t < next_tick) continue;
    next_tick = std::max(next_tick + period, t);
    const bool stale = joystick.stale(t);
    if (stale && !was_stale)
      ROS_WARN_STREAM("joystick_teleop: device " << config.device << ": no event for " << config.stale_timeout
                                                 << " s with the deadman held: zero until the next event");
    was_stale = stale;
    if (const auto command = joystick.tick(t)) ros_layer::publishCommand(publisher, *command);
    ros::spinOnce();
  }
  ros_layer::publishFinalZero(publisher);
  ROS_INFO("joystick_teleop: stopped, zero command sent");
  ros::shutdown();
  return 0;
}
