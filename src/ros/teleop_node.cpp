#include "amigobot_tracking/ros/teleop_node.h"

#include <signal.h>

#include <csignal>

#include <ros/ros.h>
#include <std_srvs/Empty.h>

#include "amigobot_tracking/ros/conversions.h"

namespace amigobot_tracking {
namespace ros_layer {

namespace {
volatile std::sig_atomic_t g_stop_signal = 0;
void onStopSignal(int signal) { g_stop_signal = signal; }
}  // namespace

void installStopSignals() {
  struct sigaction action {};
  action.sa_handler = &onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: poll() returns EINTR
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal, &action, nullptr);
}

int stopSignal() { return g_stop_signal; }

void publishCommand(const ros::Publisher& publisher, const core::Twist2& command) {
  publisher.publish(toTwist(command));
}

void publishFinalZero(const ros::Publisher& publisher, double linger) {
  if (!ros::ok()) return;
  publishCommand(publisher, core::Twist2());
  // roscpp sends from its own threads; wait until the queue has had time to drain.
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(linger);
  while (ros::WallTime::now() < end && publisher.getNumSubscribers() > 0) ros::WallDuration(0.02).sleep();
}

bool enableMotors(ros::NodeHandle& nh, const std::string& program, double timeout) {
  const std::string service = nh.resolveName("enable_motors");
  if (!ros::service::waitForService(service, ros::Duration(timeout))) {
    ROS_ERROR_STREAM(program << ": " << service << " did not appear within " << timeout
                             << " s: motors not enabled (is the driver running in this namespace?)");
    return false;
  }
  std_srvs::Empty call;
  if (!ros::service::call(service, call)) {
    ROS_ERROR_STREAM(program << ": " << service << " failed: motors not enabled");
    return false;
  }
  ROS_INFO_STREAM(program << ": motors enabled through " << service);
  return true;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
