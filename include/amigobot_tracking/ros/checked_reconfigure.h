// A dynamic_reconfigure server that can refuse a set and say so to the client. The Server of
// dynamic_reconfigure (1.7, Debian 12) answers every set_parameters call with success, so a
// set the node refused looked taken: `dynparam set` printed nothing and exited 0. Here the
// node's check returns "" (taken) or why not; a refused set changes nothing (the values in
// force stay on parameter_updates and the parameter server) and the service call fails with
// the reason, which `dynparam set` prints (its client raises) before exiting 1. A value
// outside the .cfg's range is refused naming the range instead of being clamped silently.
// Same topics, service and parameters as dynamic_reconfigure::Server: dynparam and the
// reconfigure GUIs work unchanged.
#pragma once

#include <functional>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>

#include <dynamic_reconfigure/Config.h>
#include <dynamic_reconfigure/ConfigDescription.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <ros/ros.h>

namespace amigobot_tracking {
namespace ros_layer {

template <class Config>
class CheckedReconfigure {
 public:
  // check(requested): "" to take every entry of `requested`, else why the set is refused.
  using Check = std::function<std::string(const Config& requested)>;

  // `in_force`: the values the node runs with (from its own parameters), published at once.
  CheckedReconfigure(ros::NodeHandle pnh, const Config& in_force, Check check)
      : pnh_(pnh), check_(std::move(check)), config_(in_force) {
    descriptions_ = pnh_.advertise<dynamic_reconfigure::ConfigDescription>("parameter_descriptions", 1, true);
    descriptions_.publish(Config::__getDescriptionMessage__());
    updates_ = pnh_.advertise<dynamic_reconfigure::Config>("parameter_updates", 1, true);
    publish();
    service_ = pnh_.advertiseService("set_parameters", &CheckedReconfigure::onSet, this);
  }

 private:
  bool onSet(dynamic_reconfigure::Reconfigure::Request& req, dynamic_reconfigure::Reconfigure::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    Config requested = config_;  // entries the request leaves out keep their values
    requested.__fromMessage__(req.config);
    std::string refused = outOfRange(requested);
    if (refused.empty()) refused = check_(requested);
    // roscpp answers a service callback that throws with failure and this text.
    if (!refused.empty()) throw std::runtime_error("reconfigure refused, nothing changed: " + refused);
    config_ = requested;
    publish();
    config_.__toMessage__(res.config);
    return true;
  }

  // The entries the .cfg's range would clamp, with the range.
  static std::string outOfRange(const Config& requested) {
    Config clamped = requested;
    clamped.__clamp__();
    dynamic_reconfigure::Config asked, kept, low, high;
    requested.__toMessage__(asked);
    clamped.__toMessage__(kept);
    Config::__getMin__().__toMessage__(low);
    Config::__getMax__().__toMessage__(high);
    std::ostringstream why;
    for (std::size_t i = 0; i < asked.doubles.size(); ++i) {
      if (asked.doubles[i].value == kept.doubles[i].value) continue;
      why << (why.tellp() > 0 ? "; " : "") << asked.doubles[i].name << " = " << asked.doubles[i].value
          << " is outside " << low.doubles[i].value << " .. " << high.doubles[i].value;
    }
    for (std::size_t i = 0; i < asked.ints.size(); ++i) {
      if (asked.ints[i].value == kept.ints[i].value) continue;
      why << (why.tellp() > 0 ? "; " : "") << asked.ints[i].name << " = " << asked.ints[i].value << " is outside "
          << low.ints[i].value << " .. " << high.ints[i].value;
    }
    return why.str();
  }

  void publish() {
    config_.__toServer__(pnh_);
    dynamic_reconfigure::Config msg;
    config_.__toMessage__(msg);
    updates_.publish(msg);
  }

  ros::NodeHandle pnh_;
  Check check_;
  std::mutex mutex_;  // one set at a time
  Config config_;     // the values in force
  ros::Publisher descriptions_, updates_;
  ros::ServiceServer service_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
