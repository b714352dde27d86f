// keyboard_teleop: drives a robot from the terminal it runs in, with teleop_twist_keyboard's
// key layout (teleop/keyboard.h), publishing cmd_vel (geometry_msgs/Twist) at `rate`. The
// robot stops when no key arrives for key_timeout, on k or space, and when the node ends
// (Ctrl-C, SIGTERM, the terminal closing): a last zero, and the terminal as it was.
// Needs a terminal: run it with rosrun in its own one, or roslaunch with launch-prefix="xterm -e".
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include "amigobot_tracking/ros/node_command_line.h"
#include "amigobot_tracking/ros/param_reader.h"
#include "amigobot_tracking/ros/robot_source.h"
#include "amigobot_tracking/ros/teleop_node.h"
#include "amigobot_tracking/teleop/keyboard.h"
#include "amigobot_tracking/teleop/terminal.h"

using namespace amigobot_tracking;

const ros_layer::NodeHelp kHelp{
    "Keyboard tele-operation with teleop_twist_keyboard's keys: u i o / j k l / m , . move, k or space "
    "stops, q/z both speeds +/-10 %, w/x linear only, e/c angular only, Ctrl-C quits. A differential-drive "
    "robot has no holonomic mode: Shift changes nothing. Publishes cmd_vel (geometry_msgs/Twist) at `rate`; "
    "zero when no key came for key_timeout (hold a key to keep moving) and on exit. Run it in its own "
    "terminal: rosrun amigobot_tracking keyboard_teleop cmd_vel:=/target/cmd_vel",
    "speed, turn, speed_max, turn_max, rate, key_timeout, enable_motors: config/teleop.yaml "
    "(include/amigobot_tracking/teleop/keyboard.h)."};

namespace {

double now() { return ros::WallTime::now().toSec(); }

void show(const std::string& line) {
  std::printf("\r%s\033[K", line.c_str());  // one status line, rewritten in place
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  ros_layer::initNode(argc, argv, "keyboard_teleop", kHelp, ros::init_options::NoSigintHandler);
  ros_layer::installStopSignals();
  ros::NodeHandle nh, pnh("~");
  // The speed ceilings default to the robot file's diamond and may only be smaller.
  ros_layer::RobotSource source;
  std::string error = ros_layer::readFields(pnh, ros_layer::robotSourceFields(), &source);
  aria::RobotParams robot;
  if (error.empty()) {
    try {
      robot = ros_layer::loadRobot(source);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  teleop::KeyboardConfig config;
  config.speed_max = robot.v_max;
  config.turn_max = robot.w_max;
  if (error.empty()) error = ros_layer::readParams(pnh, teleop::keyboardFields(), &config);
  if (error.empty()) {
    error = core::diamondInsideError(robot, config.speed_max, config.turn_max, "speed_max", "turn_max", robot.origin());
    if (!error.empty()) error = "~" + error;
  }
  if (!ros_layer::configLoaded("keyboard_teleop", error)) return 1;
  std::unique_ptr<teleop::RawTerminal> terminal;
  try {
    terminal = std::make_unique<teleop::RawTerminal>(STDIN_FILENO);
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("keyboard_teleop: " << e.what() << ": run it in its own terminal (rosrun amigobot_tracking "
                                            "keyboard_teleop cmd_vel:=/target/cmd_vel) or with "
                                            "launch-prefix=\"xterm -e\"; nothing published");
    return 1;
  }
  ros::Publisher publisher = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  if (config.enable_motors) ros_layer::enableMotors(nh, "keyboard_teleop");

  std::printf("%s", teleop::keyHelp().c_str());
  std::printf("Publishing %s at %g Hz; stop after %g s without a key.\n", publisher.getTopic().c_str(), config.rate,
              config.key_timeout);
  teleop::KeyboardTeleop keys(config);
  const double period = 1.0 / config.rate;
  double next_tick = now();
  std::string shown, why = "terminal closed";
  while (ros::ok() && ros_layer::stopSignal() == 0) {
    std::string typed;
    const int wait_ms = static_cast<int>(std::max(0.0, next_tick - now()) * 1000.0);
    if (!terminal->readKeys(wait_ms, &typed)) break;
    bool quit = false;
    for (char key : typed) quit = keys.onKey(key, now()) == teleop::KeyAction::kQuit || quit;
    if (quit) {
      why = "quit key";
      break;
    }
    const double t = now();
    if (t < next_tick) continue;
    next_tick = std::max(next_tick + period, t);  // late ticks are not made up in a burst
    const core::Twist2 command = keys.command(t);
    ros_layer::publishCommand(publisher, command);
    const std::string line = keys.status(command);
    if (line != shown) show(shown = line);
    ros::spinOnce();
  }
  if (ros_layer::stopSignal() != 0) why = std::string("signal ") + std::to_string(ros_layer::stopSignal());
  ros_layer::publishFinalZero(publisher);
  terminal.reset();  // the terminal as it was, before anything else is printed
  std::printf("\n");
  ROS_INFO_STREAM("keyboard_teleop: stopped (" << why << "), zero command sent");
  ros::shutdown();
  return 0;
}
