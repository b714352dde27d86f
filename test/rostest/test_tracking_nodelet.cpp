// rostest: the tracking nodelet in a nodelet manager (tracking_nodelet.test), in the
// scripted world of tracking_world.h. Checks: zero while disabled, inside the diamond when
// enabled, one zero on disable, zero when the target tf stops and a gentle restart when it
// comes back, virtual obstacle topic/services, reconfigure refusals, markers, diagnostics.
// The parameter loaders' refusals: test_tracking_param_loading.cpp (the same .test runs both).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <geometry_msgs/PointStamped.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>
#include <visualization_msgs/MarkerArray.h>

#include "amigobot_tracking/RemoveVirtualObstacle.h"
#include "child_process.h"
#include "tracking_world.h"

namespace tracking_nodelet_test {

using namespace amigobot_tracking;
using namespace tracking_world;

// The cases share one nodelet and run in this order, in the scripted world, which exists only
// while they run (the executable is every gtest rostest's: cmake/rostests.cmake).
class TrackingNodelet : public testing::Test {
 protected:
  static void SetUpTestSuite() { world = new World; }
  static void TearDownTestSuite() {
    delete world;
    world = nullptr;
  }
  static inline World* world = nullptr;
};

TEST_F(TrackingNodelet, StartsDisabledAndCommandsNothing) {
  ASSERT_TRUE(ros::service::waitForService("tracking/enable", ros::Duration(kTimeout)));
  const ros::Time since = ros::Time::now();
  // Several control periods with fresh inputs: the state says disabled, cmd_vel stays silent.
  ASSERT_TRUE(waitFor([&] { return world->statesSince(since).size() >= 20; }));
  for (const TrackingState& s : world->statesSince(since)) {
    EXPECT_FALSE(s.enabled);
    EXPECT_EQ(s.status, "disabled");
  }
  for (const auto& c : world->commandsSince(ros::WallTime(0))) EXPECT_TRUE(isZero(c.twist));
}

TEST_F(TrackingNodelet, EnabledCommandsStayInsideTheDiamond) {
  ASSERT_TRUE(trigger("tracking/enable"));
  const ros::WallTime since = ros::WallTime::now();
  ASSERT_TRUE(waitFor([&] { return world->commandsSince(since).size() >= 60; }));
  const double v_max = param("tracking/v_max"), w_max = param("tracking/w_max");
  int moving = 0;
  for (const auto& c : world->commandsSince(since)) {
    EXPECT_LE(diamondNorm(c.twist, v_max, w_max), 1.0 + 1e-9) << c.twist;
    if (!isZero(c.twist)) ++moving;
  }
  EXPECT_GT(moving, 40);
  // The laser reached the controller through the MessageFilter: pillar disks + 1 virtual.
  const std::vector<TrackingState> states = world->statesSince(ros::Time(0));
  ASSERT_FALSE(states.empty());
  EXPECT_GE(states.back().obstacles, 2);
  EXPECT_EQ(states.back().status, "tracking");
  EXPECT_LT(states.back().e_norm, states.back().rho);
}

namespace {

// One set of doubles through tracking/set_parameters: true when taken, *in_force = the
// values the node answered with.
bool reconfigureTracking(const std::vector<std::pair<std::string, double>>& values,
                         dynamic_reconfigure::Config* in_force = nullptr) {
  dynamic_reconfigure::Reconfigure srv;
  for (const auto& [name, value] : values) {
    dynamic_reconfigure::DoubleParameter p;
    p.name = name;
    p.value = value;
    srv.request.config.doubles.push_back(p);
  }
  const bool taken = ros::service::call("tracking/set_parameters", srv);
  if (in_force) *in_force = srv.response.config;
  return taken;
}

double entry(const dynamic_reconfigure::Config& config, const std::string& name) {
  for (const auto& d : config.doubles) {
    if (d.name == name) return d.value;
  }
  return std::nan("");
}

}  // namespace

// The case: v_max 2, w_max 10 against the robot file's 0.3 m/s. Before, v_max was
// capped to robot_v_max without a word, w_max taken, and the call answered success.
TEST_F(TrackingNodelet, ReconfigureBeyondTheRobotLimitIsRefusedAndFails) {
  ASSERT_TRUE(ros::service::waitForService("tracking/set_parameters", ros::Duration(kTimeout)));
  const double v_max = param("tracking/v_max"), w_max = param("tracking/w_max");
  EXPECT_FALSE(reconfigureTracking({{"v_max", 2.0}, {"w_max", 10.0}})) << "a refused set must fail the call";
  EXPECT_DOUBLE_EQ(param("tracking/v_max"), v_max) << "the refused set changed the parameter server";
  EXPECT_DOUBLE_EQ(param("tracking/w_max"), w_max);
  const ros::WallTime since = ros::WallTime::now();
  ASSERT_TRUE(waitFor([&] { return world->commandsSince(since).size() >= 20; }));
  for (const auto& c : world->commandsSince(since)) {
    EXPECT_LE(diamondNorm(c.twist, v_max, w_max), 1.0 + 1e-9) << c.twist;
  }
  // A value outside the .cfg's range is refused naming the range, not clamped.
  EXPECT_FALSE(reconfigureTracking({{"k_d", 50.0}}));
  // What a user sees: `dynparam set` fails, naming the limit (Debian's python3 first: a
  // python3 of pyenv or a venv on PATH has no roslib).
  std::string printed;
  const int status = amigobot_test::runCommand("PATH=/usr/bin:$PATH rosrun dynamic_reconfigure dynparam set /tracking \"{v_max: 2.0, w_max: 10.0}\"", &printed);
  EXPECT_NE(status, 0) << printed;
  EXPECT_NE(printed.find("the robot's v_max"), std::string::npos) << printed;
  // A set inside the limits is taken and answered with the values in force.
  dynamic_reconfigure::Config answer;
  ASSERT_TRUE(reconfigureTracking({{"v_max", 0.25}}, &answer));
  EXPECT_DOUBLE_EQ(entry(answer, "v_max"), 0.25);
  EXPECT_DOUBLE_EQ(param("tracking/v_max"), 0.25);
  ASSERT_TRUE(reconfigureTracking({{"v_max", v_max}}));  // back to the launch value for the following tests
}

TEST_F(TrackingNodelet, DisableSendsOneZeroThenNothingMoves) {
  ASSERT_TRUE(trigger("tracking/disable"));
  const ros::WallTime after = ros::WallTime::now();
  ros::WallDuration(1.5).sleep();
  // The zero is published before the service answers, after any command of a cycle in
  // flight (same publisher, ordered), so it is the last command; then cmd_vel stays silent.
  const std::vector<World::Cmd> late = world->commandsSince(after - ros::WallDuration(0.2));
  ASSERT_FALSE(late.empty());
  EXPECT_TRUE(isZero(late.back().twist));
  EXPECT_TRUE(world->commandsSince(after + ros::WallDuration(0.5)).empty());
  const std::vector<TrackingState> states = world->statesSince(ros::Time::now() - ros::Duration(0.5));
  ASSERT_FALSE(states.empty());
  EXPECT_FALSE(states.back().enabled);
}

TEST_F(TrackingNodelet, ZeroAfterTheTargetTfStopsAndGentleRestart) {
  ASSERT_TRUE(trigger("tracking/enable"));
  ASSERT_TRUE(waitFor([&] {
    const auto s = world->statesSince(ros::Time::now() - ros::Duration(0.5));
    return !s.empty() && s.back().status == "tracking";
  }));
  world->target_on = false;
  // After pose_timeout (1 s) the nodelet must command zero and say why.
  ASSERT_TRUE(waitFor([&] {
    const auto s = world->statesSince(ros::Time::now() - ros::Duration(0.5));
    return !s.empty() && s.back().status.find("target") != std::string::npos;
  }));
  const ros::WallTime stale_since = ros::WallTime::now();
  ros::WallDuration(1.0).sleep();
  const std::vector<World::Cmd> stale = world->commandsSince(stale_since);
  ASSERT_GE(stale.size(), 5u);  // zero is still sent every period while enabled
  for (const auto& c : stale) EXPECT_TRUE(isZero(c.twist)) << c.twist;

  const ros::Time resumed = ros::Time::now();
  world->target_on = true;
  ASSERT_TRUE(waitFor([&] {
    for (const auto& s : world->statesSince(resumed)) {
      if (s.valid) return true;
    }
    return false;
  }));
  // The first step after the restart has |e|/rho <= 1/2 (rho restarts at max(rho_0, 2|e|)).
  for (const auto& s : world->statesSince(resumed)) {
    if (!s.valid) continue;
    EXPECT_LE(s.e_norm / s.rho, 0.5 + 1e-9);
    break;
  }
  const ros::WallTime since = ros::WallTime::now();
  ASSERT_TRUE(waitFor([&] { return world->commandsSince(since).size() >= 20; }));
  for (const auto& c : world->commandsSince(since)) {
    EXPECT_LE(diamondNorm(c.twist, param("tracking/v_max"), param("tracking/w_max")), 1.0 + 1e-9);
  }
  // The resume ramp: the first motion after the restart is at most one control period
  // (1/20 s) of the default accelerations (0.3 m/s^2, 1.745 rad/s^2) away from zero.
  for (const auto& c : world->commandsSince(ros::WallTime(resumed.toSec()))) {
    if (isZero(c.twist)) continue;
    EXPECT_LE(std::abs(c.twist.linear.x), 0.3 / 20.0 + 1e-9) << c.twist;
    EXPECT_LE(std::abs(c.twist.angular.z), 1.745 / 20.0 + 1e-9) << c.twist;
    break;
  }
  ASSERT_TRUE(trigger("tracking/disable"));
}

TEST_F(TrackingNodelet, UnusableScansCountAsNoScan) {
  ASSERT_TRUE(trigger("tracking/enable"));
  auto status_has = [&](const std::string& word) {
    const auto s = world->statesSince(ros::Time::now() - ros::Duration(0.5));
    return !s.empty() && s.back().status.find(word) != std::string::npos;
  };
  ASSERT_TRUE(waitFor([&] { return status_has("tracking"); }));
  world->scan_broken = true;  // scans keep arriving, but none can be used
  ASSERT_TRUE(waitFor([&] { return status_has("scan"); }));
  const ros::WallTime since = ros::WallTime::now();
  ros::WallDuration(0.5).sleep();
  for (const auto& c : world->commandsSince(since)) EXPECT_TRUE(isZero(c.twist)) << c.twist;
  world->scan_broken = false;
  EXPECT_TRUE(waitFor([&] { return status_has("tracking"); }));
  ASSERT_TRUE(trigger("tracking/disable"));
}

TEST_F(TrackingNodelet, VirtualObstaclesFromYamlTopicAndServices) {
  ASSERT_TRUE(waitFor([&] { return world->virtualObstacles().obstacles.size() == 1; }));
  EXPECT_EQ(world->virtualObstacles().obstacles[0].id, "start_box");
  VirtualObstacle o;
  o.id = "pole";
  o.center.x = 3.0;
  o.center.y = -1.0;
  o.radius = 0.2;
  world->publishVirtual(o);
  ASSERT_TRUE(waitFor([&] { return world->virtualObstacles().obstacles.size() == 2; }));
  EXPECT_EQ(world->virtualObstacles().obstacles[1].id, "pole");
  EXPECT_EQ(world->virtualObstacles().header.frame_id, "map");

  // rviz "Publish Point": a disk of clicked_point_radius, transformed into map.
  ros::NodeHandle nh;
  ros::Publisher clicked = nh.advertise<geometry_msgs::PointStamped>("clicked_point", 1, true);
  geometry_msgs::PointStamped click;
  click.header.frame_id = "map";
  click.point.x = -2.0;
  click.point.y = 0.5;
  clicked.publish(click);
  ASSERT_TRUE(waitFor([&] { return world->virtualObstacles().obstacles.size() == 3; }));
  const VirtualObstacle added = world->virtualObstacles().obstacles[2];
  EXPECT_EQ(added.id.rfind("click_", 0), 0u) << added.id;
  EXPECT_DOUBLE_EQ(added.radius, param("tracking/clicked_point_radius"));
  EXPECT_DOUBLE_EQ(added.center.x, -2.0);
  EXPECT_DOUBLE_EQ(added.center.y, 0.5);

  // Interactive markers: dragging moves the obstacle, the menu's Delete removes it.
  ros::Publisher feedback =
      nh.advertise<visualization_msgs::InteractiveMarkerFeedback>("tracking/obstacle_markers/feedback", 10);
  ASSERT_TRUE(waitFor([&] { return feedback.getNumSubscribers() > 0; }));
  visualization_msgs::InteractiveMarkerFeedback drag;
  drag.header.frame_id = "map";
  drag.client_id = "test";
  drag.marker_name = added.id;
  drag.event_type = visualization_msgs::InteractiveMarkerFeedback::POSE_UPDATE;
  drag.pose.position.x = -3.0;
  drag.pose.position.y = 1.5;
  drag.pose.orientation.w = 1.0;
  feedback.publish(drag);
  ASSERT_TRUE(waitFor([&] {
    const auto a = world->virtualObstacles();
    return a.obstacles.size() == 3 && a.obstacles[2].center.x == -3.0 && a.obstacles[2].center.y == 1.5;
  }));
  visualization_msgs::InteractiveMarkerFeedback remove_click = drag;
  remove_click.event_type = visualization_msgs::InteractiveMarkerFeedback::MENU_SELECT;
  remove_click.menu_entry_id = 1;
  feedback.publish(remove_click);
  ASSERT_TRUE(waitFor([&] { return world->virtualObstacles().obstacles.size() == 2; }));

  RemoveVirtualObstacle remove;
  remove.request.id = "start_box";
  ASSERT_TRUE(ros::service::call("tracking/remove_virtual_obstacle", remove));
  EXPECT_TRUE(remove.response.success);
  ASSERT_TRUE(ros::service::call("tracking/remove_virtual_obstacle", remove));
  EXPECT_FALSE(remove.response.success);  // already gone
  ASSERT_TRUE(waitFor([&] {
    const auto a = world->virtualObstacles();
    return a.obstacles.size() == 1 && a.obstacles[0].id == "pole";
  }));
  ASSERT_TRUE(trigger("tracking/clear_virtual_obstacles"));
  ASSERT_TRUE(waitFor([&] { return world->virtualObstacles().obstacles.empty(); }));
}

TEST_F(TrackingNodelet, MarkersAndDiagnostics) {
  ros::NodeHandle nh;
  std::mutex mutex;
  visualization_msgs::MarkerArray markers;
  diagnostic_msgs::DiagnosticStatus tracking_status;
  ros::Subscriber marker_sub = nh.subscribe<visualization_msgs::MarkerArray>(
      "tracking/markers", 1, [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        markers = *m;
      });
  ros::Subscriber diag_sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& d) {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& s : d->status) {
          if (s.name.find("tracking") != std::string::npos) tracking_status = s;
        }
      });
  ASSERT_TRUE(waitFor([&] {
    std::lock_guard<std::mutex> lock(mutex);
    return !markers.markers.empty() && !tracking_status.values.empty();
  }));
  std::lock_guard<std::mutex> lock(mutex);
  bool body = false, diamond = false, text = false;
  for (const auto& m : markers.markers) {
    body = body || m.ns == "body";
    diamond = diamond || m.ns == "diamond";
    text = text || m.ns == "text";
  }
  EXPECT_TRUE(body && diamond && text);
  std::vector<std::string> keys;
  for (const auto& kv : tracking_status.values) keys.push_back(kv.key);
  for (const char* key : {"control rate measured [Hz]", "robot pose age [s]", "scan age [s]", "saturation ratio",
                          "rho [m]", "min clearance [m]"}) {
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
  }
}

}  // namespace tracking_nodelet_test
