// End to end: nodelets with an invalid parameter refuse to start and the motors stay off
// (bad_parameters.test), judged from the emulator's status and command journal (judge.h).
// One case of the test_e2e executable (main in test_e2e.cpp; the .test file picks the case).
#include <gtest/gtest.h>

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include <nodelet/NodeletLoad.h>
#include <nodelet/NodeletUnload.h>
#include <rosgraph_msgs/Log.h>

#include "experiment.h"
#include "judge.h"

using e2e::EmulatorStatus;
using e2e::requiredParam;

namespace {

// FATAL lines on /rosout (the nodelets log through their manager; rostest starts no rosout
// aggregator here). connected(n): n publishers (this node and the manager) are connected,
// so no line of theirs can be missed any more.
class FatalLog {
 public:
  explicit FatalLog(ros::NodeHandle& nh) { sub_ = nh.subscribe("/rosout", 100, &FatalLog::onLog, this); }
  bool connected(std::uint32_t publishers, double timeout) {
    return e2e::waitFor([&] { return sub_.getNumPublishers() >= publishers; }, timeout);
  }
  bool waitForMention(const std::string& text, double timeout) {
    return e2e::waitFor([&] {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& line : lines_) {
        if (line.find(text) != std::string::npos) return true;
      }
      return false;
    }, timeout);
  }

 private:
  void onLog(const rosgraph_msgs::Log::ConstPtr& log) {
    if (log->level < rosgraph_msgs::Log::FATAL) return;
    std::lock_guard<std::mutex> lock(mutex_);
    lines_.push_back(log->msg);
  }
  ros::Subscriber sub_;
  std::mutex mutex_;
  std::vector<std::string> lines_;
};

bool loadNodelet(const std::string& manager, const std::string& name, const std::string& type) {
  nodelet::NodeletLoad load;
  load.request.name = name;
  load.request.type = type;
  return ros::service::waitForService(manager + "/load_nodelet", ros::Duration(30.0)) &&
         ros::service::call(manager + "/load_nodelet", load) && load.response.success;
}

void unloadNodelet(const std::string& manager, const std::string& name) {
  nodelet::NodeletUnload unload;
  unload.request.name = name;
  ros::service::call(manager + "/unload_nodelet", unload);
}

// Watches the emulator for `duration` [s]: true if the motors were ever on (or the robot
// ever opened, when `open_counts`).
bool everEnabled(e2e::GroundTruth& truth, double duration, bool open_counts) {
  return e2e::waitFor([&] {
    const EmulatorStatus s = truth.truth();
    return s.motors || (open_counts && s.open);
  }, duration);
}

}  // namespace

// a driver or tracking nodelet with an invalid parameter refuses to start with a
// FATAL naming the parameter, and the robot's motors are never enabled (emulator status).
// The test loads each nodelet itself into the .test file's bare manager, one bad value at
// a time; enable_motors is true for the bad drivers, so only the refusal keeps them off.
TEST(E2E, BadParametersAreRefusedAndTheMotorsStayOff) {
  ros::NodeHandle nh;
  FatalLog fatal(nh);
  ASSERT_TRUE(fatal.connected(2, 30.0)) << "the manager's /rosout is not connected";
  e2e::GroundTruth truth(requiredParam<int>("status_port"));
  const std::string manager = requiredParam<std::string>("manager");
  const std::string port = "127.0.0.1:" + std::to_string(requiredParam<int>("tcp_port"));
  // 3 s of watching: 30 SIP periods, ample for a driver that wrongly started to connect
  // (a good one opens within 0.5 s here) and enable the motors.
  const double watch = 3.0;
  struct DriverCase {
    std::string param;
    XmlRpc::XmlRpcValue value;
  };
  const std::vector<DriverCase> drivers = {{"v_max", -0.3}, {"w_max", 99.0}, {"command_mode", "vel3"}};
  for (const auto& c : drivers) {
    const std::string name = "/bad_driver_" + c.param;
    ros::param::set(name + "/port", port);
    ros::param::set(name + "/enable_motors", true);
    ros::param::set(name + "/" + c.param, c.value);
    EXPECT_TRUE(loadNodelet(manager, name, "amigobot_tracking/Driver")) << "the manager must survive";
    EXPECT_TRUE(fatal.waitForMention("~" + c.param, 10.0)) << "no FATAL naming ~" << c.param;
    EXPECT_FALSE(everEnabled(truth, watch, true)) << "driver with bad ~" << c.param << " opened the robot";
    unloadNodelet(manager, name);
  }

  // The tracking nodelet next to a good driver that connects but leaves the motors to the
  // operator (enable_motors false, as amigobot.launch): a refused tracking nodelet must put
  // no motion on the wire and never get the motors enabled.
  ros::param::set("/driver/port", port);
  ros::param::set("/driver/enable_motors", false);
  ASSERT_TRUE(loadNodelet(manager, "/driver", "amigobot_tracking/Driver"));
  ASSERT_TRUE(e2e::waitFor([&] { return truth.truth().open; }, 30.0)) << "the good driver never connected";
  const std::vector<DriverCase> trackings = {{"k_d", -0.15}, {"rho_inf", 0.0}, {"control_rate", 0.0}};
  for (const auto& c : trackings) {
    const std::string name = "/bad_tracking_" + c.param;
    ros::param::set(name + "/require_scan", false);
    ros::param::set(name + "/autostart", true);
    ros::param::set(name + "/" + c.param, c.value);
    EXPECT_TRUE(loadNodelet(manager, name, "amigobot_tracking/Tracking"));
    EXPECT_TRUE(fatal.waitForMention(c.param, 10.0)) << "no FATAL naming " << c.param;
    EXPECT_FALSE(ros::service::exists(name + "/enable", false));
    EXPECT_FALSE(everEnabled(truth, watch, false)) << "motors enabled with bad tracking ~" << c.param;
    unloadNodelet(manager, name);
  }
  for (const auto& c : e2e::readCommandLog(requiredParam<std::string>("command_log"))) {
    EXPECT_TRUE(c.v == 0.0 && c.w == 0.0) << "motion on the wire: " << c.command << " at t = " << c.t;
  }
  unloadNodelet(manager, "/driver");
}
