// rostest: with a bad parameter (tf_rate 10 Hz, below 20) the nodelet logs a FATAL naming
// ~tf_rate and starts nothing: no map -> odom, no services, even with scans and odometry
// arriving; the manager survives and unloads it. The standalone localization_node with a
// missing map exits 1 after its FATAL, every time, never aborting.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <atomic>
#include <mutex>
#include <string>

#include <nodelet/loader.h>
#include <rosgraph_msgs/Log.h>
#include <tf2_msgs/TFMessage.h>

#include "child_process.h"
#include "synthetic_robot.h"

TEST(LocalizationBadParam, NamesTheParameterAndStartsNothing) {
  ros::NodeHandle nh;
  std::atomic<int> map_to_odom{0};
  ros::Subscriber tf_sub = nh.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) map_to_odom += t.header.frame_id == "map";
  });
  std::mutex mutex;
  std::string fatal;
  ros::Subscriber log_sub = nh.subscribe<rosgraph_msgs::Log>("/rosout", 100, [&](const rosgraph_msgs::Log::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    if (msg->level == rosgraph_msgs::Log::FATAL) fatal += msg->msg + "\n";
  });
  // The log subscription is connected (this process publishes /rosout) before the load.
  const ros::WallTime connect_end = ros::WallTime::now() + ros::WallDuration(10.0);
  while (log_sub.getNumPublishers() == 0 && ros::WallTime::now() < connect_end) ros::WallDuration(0.05).sleep();
  ros::param::set("/localization/mode", "mapping");
  ros::param::set("/localization/tf_rate", 10.0);
  amigobot_test::SyntheticRobot robot(amigobot_test::kLoopStart, amigobot_test::Pose2{});
  nodelet::Loader loader(false);
  EXPECT_TRUE(loader.load("/localization", "amigobot_tracking/Localization", {}, {}));  // the manager survives
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(6.0);
  while (ros::WallTime::now() < end) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (fatal.find("~tf_rate") != std::string::npos) break;
    }
    ros::WallDuration(0.1).sleep();
  }
  ros::WallDuration(2.0).sleep();  // scans keep coming: still nothing may start
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_NE(fatal.find("~tf_rate: must be"), std::string::npos) << "FATAL log: " << fatal;
  }
  EXPECT_EQ(map_to_odom.load(), 0);
  EXPECT_FALSE(ros::service::exists("localization/save_map", false));
  EXPECT_FALSE(ros::service::exists("localization/global_localization", false));
  EXPECT_TRUE(loader.unload("/localization"));
}

// Before: SIGABRT (boost::lock_error) after the FATAL in 3 of 20 runs.
TEST(LocalizationBadParam, StandaloneNodeWithAMissingMapExitsCleanlyEveryTime) {
  const std::string map = "/nonexistent_amigobot_maps/lab.yaml";
  int clean = 0;
  for (int run = 0; run < 20; ++run) {
    std::string printed;
    const int status = amigobot_test::runCommand(std::string(AMIGOBOT_LOCALIZATION_NODE) + " __name:=missing_map_" +
                                                     std::to_string(run) + " _mode:=localization _map_file:=" + map,
                                                 &printed);
    const bool signalled = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) > 128);
    EXPECT_FALSE(signalled) << "run " << run << " died by a signal:\n" << printed;
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << "run " << run << ": status " << status << "\n" << printed;
    EXPECT_EQ(printed.find("terminate called"), std::string::npos) << "run " << run << ":\n" << printed;
    EXPECT_NE(printed.find(map), std::string::npos) << "the FATAL must name the map, run " << run << ":\n" << printed;
    clean += !signalled && WIFEXITED(status) && WEXITSTATUS(status) == 1;
  }
  std::printf("localization_node with a missing map: %d of 20 runs exited 1 cleanly\n", clean);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_localization_bad_param");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
