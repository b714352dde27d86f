// The driver's watch of what it cannot see through the link's own state: a ROS master that
// is gone (nobody could stop the robot through ROS) and a link that carries only the
// robot's half (the robot stops by its watchdog, the driver must say why).
#include "amigobot_tracking/ros/driver.h"

namespace amigobot_tracking {
namespace ros_layer {

void AmigobotDriver::checkMaster() {
  const MasterWatch::State master = master_->state();
  if (!master_stop_ && master.unreachable_for > params_.master_timeout) {
    master_stop_ = true;
    client_->setVelocity({});
    client_->requestMotors(false);
    ROS_ERROR_STREAM_NAMED("driver", "ROS master unreachable for " << master.unreachable_for
                                                                    << " s (master_timeout " << params_.master_timeout
                                                                    << " s): robot stopped, motors disabled; they "
                                                                       "stay disabled until enable_motors");
    updater_.force_update();
  }
  if (master.registrations != master_registrations_) {
    master_registrations_ = master.registrations;
    ROS_INFO_STREAM_NAMED("driver", "a new ROS master answers: this process registered again ("
                                        << master.last_registration
                                        << "); the motors stay disabled until enable_motors");
  }
  if (master_stop_ && master.reachable) {
    master_stop_ = false;
    ROS_INFO_NAMED("driver", "ROS master reachable again: cmd_vel accepted; the motors stay disabled until enable_motors");
    updater_.force_update();
  }
}

void AmigobotDriver::reportOneWayLink(const aria::ClientStatus& status) {
  const bool one_way = status.link == aria::LinkState::kConnected &&
                       status.acknowledgement == aria::AcknowledgementState::kUnacknowledged;
  if (one_way) {
    ROS_ERROR_STREAM_THROTTLE_NAMED(2.0, "driver", "one-way link: the robot has not answered for "
                                                       << status.unanswered_for
                                                       << " s while its SIPs arrive; it does not hear the driver "
                                                          "and its watchdog stops it");
  }
  if (one_way != one_way_reported_) {
    one_way_reported_ = one_way;
    updater_.force_update();  // diagnostics now, not at the next 1 s tick
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
