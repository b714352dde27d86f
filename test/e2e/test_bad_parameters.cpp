// End to end: nodelets with an invalid parameter refuse to start and the motors stay off
// (bad_parameters.test), judged from the emulator's status and command journal (judge.h).
// One case of the test_e2e executable (main in test_e2e.cpp; the .test file picks the case).
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nodelet/NodeletLoad.h>
#include <nodelet/NodeletUnload.h>
#include <rosgraph_msgs/Log.h>

#include "experiment.h"
#include "judge.h"
#include "rosout_log.h"

using e2e::EmulatorStatus;
using e2e::requiredParam;

namespace {

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

// One nodelet loaded with one bad parameter: its name, its good parameters, the bad one and
// what its FATAL must say besides ~param.
struct BadNodelet {
  std::string type;  // e.g. amigobot_tracking/Driver
  std::map<std::string, XmlRpc::XmlRpcValue> good;
  std::string param;
  XmlRpc::XmlRpcValue value;
  std::string says;  // "" or e.g. "must be a number, got a string"
};

// Loads `c` into the .test file's bare manager, expects a FATAL naming ~param (and c.says),
// no ~enable service, and the motors never on (nor the robot opened, when `open_counts`)
// for `watch` [s]; unloads it.
void expectRefused(const BadNodelet& c, e2e::RosoutLog& fatal, e2e::GroundTruth& truth, double watch,
                   bool open_counts) {
  const std::string manager = requiredParam<std::string>("manager");
  const std::string name = "/bad_" + c.type.substr(c.type.find('/') + 1) + "_" + c.param;
  for (const auto& p : c.good) ros::param::set(name + "/" + p.first, p.second);
  ros::param::set(name + "/" + c.param, c.value);
  const std::size_t since = fatal.count();
  EXPECT_TRUE(loadNodelet(manager, name, c.type)) << "the manager must survive " << name;
  std::vector<std::string> texts{"~" + c.param};
  if (!c.says.empty()) texts.push_back(c.says);
  EXPECT_TRUE(fatal.waitForMentionOfAll(texts, 10.0, since)) << "no FATAL naming ~" << c.param << " " << c.says;
  EXPECT_FALSE(ros::service::exists(name + "/enable", false)) << name;
  EXPECT_FALSE(everEnabled(truth, watch, open_counts)) << c.type << " with bad ~" << c.param << " got the motors on";
  unloadNodelet(manager, name);
}

void expectNoMotionOnTheWire() {
  for (const auto& c : e2e::readCommandLog(requiredParam<std::string>("command_log"))) {
    EXPECT_TRUE(c.v == 0.0 && c.w == 0.0) << "motion on the wire: " << c.command << " at t = " << c.t;
  }
}

// A driver that connects but leaves the motors to the operator (enable_motors false, as
// amigobot.launch), for the nodelets that only command or feed it: a refused one must put no
// motion on the wire and never get the motors enabled.
void loadGoodDriver(e2e::GroundTruth& truth, const std::string& port) {
  ros::param::set("/driver/port", port);
  ros::param::set("/driver/enable_motors", false);
  ASSERT_TRUE(loadNodelet(requiredParam<std::string>("manager"), "/driver", "amigobot_tracking/Driver"));
  ASSERT_TRUE(e2e::waitFor([&] { return truth.truth().open; }, 30.0)) << "the good driver never connected";
}

XmlRpc::XmlRpcValue listOf(bool a, bool b) {
  XmlRpc::XmlRpcValue list;
  list[0] = a;
  list[1] = b;
  return list;
}

}  // namespace

// a driver or tracking nodelet with an invalid parameter refuses to start with a
// FATAL naming the parameter, and the robot's motors are never enabled (emulator status).
// The test loads each nodelet itself into the .test file's bare manager, one bad value at
// a time; enable_motors is true for the bad drivers, so only the refusal keeps them off.
TEST(E2E, BadParametersAreRefusedAndTheMotorsStayOff) {
  ros::NodeHandle nh;
  e2e::RosoutLog fatal(nh, rosgraph_msgs::Log::FATAL);
  ASSERT_TRUE(fatal.connected(2, 30.0)) << "the manager's /rosout is not connected";
  e2e::GroundTruth truth(requiredParam<int>("status_port"));
  const std::string port = "127.0.0.1:" + std::to_string(requiredParam<int>("tcp_port"));
  // 3 s of watching: 30 SIP periods, ample for a driver that wrongly started to connect
  // (a good one opens within 0.5 s here) and enable the motors.
  const double watch = 3.0;
  const std::map<std::string, XmlRpc::XmlRpcValue> driver = {{"port", port}, {"enable_motors", true}};
  for (const auto& bad : std::vector<std::pair<std::string, XmlRpc::XmlRpcValue>>{
           {"v_max", -0.3}, {"w_max", 99.0}, {"command_mode", "vel3"}}) {
    expectRefused({"amigobot_tracking/Driver", driver, bad.first, bad.second, ""}, fatal, truth, watch, true);
  }
  loadGoodDriver(truth, port);
  const std::map<std::string, XmlRpc::XmlRpcValue> tracking = {{"require_scan", false}, {"autostart", true}};
  for (const auto& bad : std::vector<std::pair<std::string, XmlRpc::XmlRpcValue>>{
           {"k_d", -0.15}, {"rho_inf", 0.0}, {"control_rate", 0.0}}) {
    expectRefused({"amigobot_tracking/Tracking", tracking, bad.first, bad.second, ""}, fatal, truth, watch, false);
  }
  expectNoMotionOnTheWire();
  unloadNodelet(requiredParam<std::string>("manager"), "/driver");
}

// Issue 24 item 4: a value of the wrong type (a string where a number is expected, a list
// where a bool or a string is, a real where an integer is) for each nodelet that drives,
// commands or feeds the robot: refused at start by a FATAL naming the parameter and the type
// it got (param_reader's wording), and the robot never moves. 2 s of watching each (20 SIP
// periods; a driver that wrongly started opens the robot within 0.5 s).
TEST(E2E, WrongParameterTypesAreRefusedAndNothingMoves) {
  ros::NodeHandle nh;
  e2e::RosoutLog fatal(nh, rosgraph_msgs::Log::FATAL);
  ASSERT_TRUE(fatal.connected(2, 30.0)) << "the manager's /rosout is not connected";
  e2e::GroundTruth truth(requiredParam<int>("status_port"));
  const std::string port = "127.0.0.1:" + std::to_string(requiredParam<int>("tcp_port"));
  const double watch = 2.0;
  const std::string got_string = "must be a number, got a string";
  const std::map<std::string, XmlRpc::XmlRpcValue> driver = {{"port", port}, {"enable_motors", true}};
  expectRefused({"amigobot_tracking/Driver", driver, "v_max", "0.3", got_string}, fatal, truth, watch, true);
  expectRefused({"amigobot_tracking/Driver", driver, "publish_tf", listOf(true, false),
                 "must be true or false, got a list"}, fatal, truth, watch, true);

  loadGoodDriver(truth, port);
  const std::map<std::string, XmlRpc::XmlRpcValue> tracking = {{"require_scan", false}, {"autostart", true}};
  expectRefused({"amigobot_tracking/Tracking", tracking, "k_d", "fast", got_string}, fatal, truth, watch, false);
  expectRefused({"amigobot_tracking/Tracking", {{"autostart", true}}, "require_scan", listOf(false, false),
                 "must be true or false, got a list"}, fatal, truth, watch, false);
  // The laser's port is the emulator's robot port: a Laser nodelet that wrongly started
  // would only fail to parse it; what matters is the refusal by name.
  const std::map<std::string, XmlRpc::XmlRpcValue> laser = {{"model", "sick_tim5xx"}, {"port", "127.0.0.1:1"}};
  expectRefused({"amigobot_tracking/Laser", laser, "stall_timeout", "long", got_string}, fatal, truth, watch, false);
  expectRefused({"amigobot_tracking/Laser", laser, "upside_down", listOf(true, true),
                 "must be true or false, got a list"}, fatal, truth, watch, false);
  const std::map<std::string, XmlRpc::XmlRpcValue> localization = {{"mode", "mapping"}};
  expectRefused({"amigobot_tracking/Localization", localization, "tf_rate", "fast", got_string}, fatal, truth, watch,
                false);
  expectRefused({"amigobot_tracking/Localization", {}, "mode", listOf(true, false), "must be a text, got a list"},
                fatal, truth, watch, false);
  expectNoMotionOnTheWire();
  unloadNodelet(requiredParam<std::string>("manager"), "/driver");
}
