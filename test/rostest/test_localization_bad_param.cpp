// rostest: with a bad parameter (tf_rate 10 Hz, below 20) the nodelet logs a FATAL naming
// ~tf_rate and starts nothing: no map -> odom, no services, even with scans and odometry
// arriving; the manager survives and unloads it. The standalone localization_node with a
// missing map exits 1 after its FATAL, every time, never aborting. A mapping map_file whose
// folder cannot be created is refused the same way at start-up, naming the path.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>

#include <nodelet/loader.h>
#include <rosgraph_msgs/Log.h>
#include <tf2_msgs/TFMessage.h>

#include "child_process.h"
#include "synthetic_robot.h"

namespace localization_bad_param_test {

namespace {

// The FATAL lines on /rosout, subscribed (this process publishes /rosout) before a load.
class FatalLog {
 public:
  FatalLog() {
    sub_ = ros::NodeHandle().subscribe<rosgraph_msgs::Log>("/rosout", 100, [this](const rosgraph_msgs::Log::ConstPtr& msg) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (msg->level == rosgraph_msgs::Log::FATAL) text_ += msg->msg + "\n";
    });
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(10.0);
    while (sub_.getNumPublishers() == 0 && ros::WallTime::now() < end) ros::WallDuration(0.05).sleep();
  }
  // Waits up to 6 s for `part` in a FATAL line.
  bool waitFor(const std::string& part) {
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(6.0); ros::WallTime::now() < end;) {
      if (text().find(part) != std::string::npos) return true;
      ros::WallDuration(0.1).sleep();
    }
    return false;
  }
  std::string text() {
    std::lock_guard<std::mutex> lock(mutex_);
    return text_;
  }

 private:
  std::mutex mutex_;
  std::string text_;
  ros::Subscriber sub_;
};

}  // namespace

TEST(LocalizationBadParam, NamesTheParameterAndStartsNothing) {
  ros::NodeHandle nh;
  std::atomic<int> map_to_odom{0};
  ros::Subscriber tf_sub = nh.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) map_to_odom += t.header.frame_id == "map";
  });
  FatalLog log;
  ros::param::set("/localization/mode", "mapping");
  ros::param::set("/localization/tf_rate", 10.0);
  amigobot_test::SyntheticRobot robot(amigobot_test::kLoopStart, amigobot_test::Pose2{});
  nodelet::Loader loader(false);
  EXPECT_TRUE(loader.load("/localization", "amigobot_tracking/Localization", {}, {}));  // the manager survives
  log.waitFor("~tf_rate");
  ros::WallDuration(2.0).sleep();  // scans keep coming: still nothing may start
  EXPECT_TRUE(log.waitFor("~tf_rate: must be")) << "FATAL log: " << log.text();
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

TEST(LocalizationBadParam, AMapFolderThatCannotBeCreatedIsRefusedAtStartUp) {
  FatalLog log;
  const std::string file = "/tmp/amigobot_not_a_folder_" + std::to_string(::getpid());
  std::ofstream(file) << "a file where the maps folder should be\n";
  const std::string map_file = file + "/maps/lab.yaml";
  ros::param::set("/mapping_refused/mode", "mapping");
  ros::param::set("/mapping_refused/map_file", map_file);
  nodelet::Loader loader(false);
  EXPECT_TRUE(loader.load("/mapping_refused", "amigobot_tracking/Localization", {}, {}));
  const std::string expected = "~map_file: " + map_file + ": cannot create the folder " + file + "/maps: " + file + " is not a folder";
  EXPECT_TRUE(log.waitFor(expected)) << "FATAL log: " << log.text();
  EXPECT_FALSE(ros::service::exists("mapping_refused/save_map", false));
  EXPECT_TRUE(loader.unload("/mapping_refused"));
  std::filesystem::remove(file);
}

}  // namespace localization_bad_param_test
