// rostest (nodelets_extreme_params.test): one manager hosting every nodelet with extreme
// in-bounds parameters, plus issue 25's crashing pair (control_rate 1e-10, delta 1e12). The
// manager must still list every loaded nodelet after they had seconds to run; the in-bounds
// tracking nodelets are live (their enable service exists), the refused one is inert.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <nodelet/NodeletList.h>
#include <ros/ros.h>

namespace nodelets_extreme_params_test {

namespace {

bool listNodelets(std::vector<std::string>* names) {
  nodelet::NodeletList list;
  if (!ros::service::call("manager/list", list)) return false;
  *names = list.response.nodelets;
  return true;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TEST(NodeletsExtremeParams, OneManagerSurvivesThemAll) {
  ASSERT_TRUE(ros::service::waitForService("manager/list", ros::Duration(30.0)));
  const std::vector<std::string> all = {"/tracking_fast", "/tracking_slow", "/tracking_refused",
                                        "/driver", "/laser", "/localization"};
  std::vector<std::string> names;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::WallTime::now() < deadline) {  // the loader's calls come in one by one
    ASSERT_TRUE(listNodelets(&names)) << "the manager stopped answering";
    if (std::all_of(all.begin(), all.end(), [&](const std::string& n) { return contains(names, n); })) break;
    ros::WallDuration(0.2).sleep();
  }
  for (const std::string& n : all) EXPECT_TRUE(contains(names, n)) << n << " not loaded";
  EXPECT_TRUE(ros::service::waitForService("tracking_fast/enable", ros::Duration(5.0)));
  EXPECT_TRUE(ros::service::waitForService("tracking_slow/enable", ros::Duration(5.0)));
  ros::WallDuration(3.0).sleep();  // let the timers, threads and reconnections run
  EXPECT_FALSE(ros::service::exists("tracking_refused/enable", false));
  ASSERT_TRUE(listNodelets(&names)) << "the manager died";
  for (const std::string& n : all) EXPECT_TRUE(contains(names, n)) << n << " gone at the end";
}

}  // namespace nodelets_extreme_params_test
