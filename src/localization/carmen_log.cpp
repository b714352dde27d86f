#include "amigobot_tracking/localization/carmen_log.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/localization/poses.h"

namespace amigobot_tracking {
namespace localization {

namespace {

struct OdomSample {
  double stamp;
  core::Pose2 pose;
};

class LineFields {
 public:
  LineFields(const std::string& line, const std::string& where) : where_(where) {
    std::istringstream in(line);
    for (std::string token; in >> token;) tokens_.push_back(token);
  }
  std::size_t size() const { return tokens_.size(); }
  double number(std::size_t i, const char* what) const {
    if (i >= tokens_.size()) fail(std::string("line ends before ") + what);
    try {
      std::size_t used = 0;
      const double value = std::stod(tokens_[i], &used);
      if (used == tokens_[i].size() && std::isfinite(value)) return value;
    } catch (const std::exception&) {
    }
    fail(std::string(what) + ": '" + tokens_[i] + "' is not a finite number");
  }
  int count(std::size_t i, const char* what, int max) const {
    const double value = number(i, what);
    if (value < 0 || value > max || value != std::floor(value)) fail(std::string(what) + ": " + tokens_[i] + " is not a count in [0, " + std::to_string(max) + "]");
    return static_cast<int>(value);
  }
  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(where_ + ": " + tokens_[0] + ": " + what); }

 private:
  std::vector<std::string> tokens_;
  std::string where_;
};

core::Pose2 poseAt(const LineFields& f, std::size_t i, const char* what) {
  return core::Pose2{f.number(i, what), f.number(i + 1, what), f.number(i + 2, what)};
}

std::vector<float> readRanges(const LineFields& f, std::size_t first, int n, double no_echo) {
  std::vector<float> ranges(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double r = f.number(first + k, "range reading");
    ranges[static_cast<std::size_t>(k)] = r >= no_echo || r <= 0.0 ? std::numeric_limits<float>::infinity() : static_cast<float>(r);
  }
  return ranges;
}

// The odometry at `stamp`, interpolated between the ODOM samples around it (held at the ends).
core::Pose2 odometryAt(const std::vector<OdomSample>& odom, double stamp) {
  const auto after = std::lower_bound(odom.begin(), odom.end(), stamp, [](const OdomSample& s, double t) { return s.stamp < t; });
  if (after == odom.begin()) return odom.front().pose;
  if (after == odom.end()) return odom.back().pose;
  const OdomSample& a = *(after - 1);
  const OdomSample& b = *after;
  const double u = b.stamp > a.stamp ? (stamp - a.stamp) / (b.stamp - a.stamp) : 0.0;
  const core::Pose2 step = compose(inverse(a.pose), b.pose);
  return compose(a.pose, core::Pose2{u * step.x, u * step.y, u * step.theta});
}

}  // namespace

CarmenLog readCarmenLog(const std::string& path, double no_echo) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the log");
  CarmenLog log;
  std::vector<OdomSample> odom;
  std::vector<core::Pose2> laser_odometry;  // the laser lines' own odometry fields
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = path + ":" + std::to_string(number);
    const LineFields f(line, where);
    if (f.size() == 0) continue;
    std::istringstream head(line);
    std::string kind;
    head >> kind;
    if (kind == "ODOM") {
      // ODOM x y theta tv rv accel ipc_timestamp ipc_hostname logger_timestamp
      odom.push_back({f.number(7, "ipc_timestamp"), poseAt(f, 1, "x y theta")});
    } else if (kind == "FLASER") {
      // FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp ipc_hostname logger_timestamp
      const int n = f.count(1, "num_readings", 10000);
      if (n < 2) f.fail("fewer than 2 readings");
      LogScan s;
      s.scan.ranges = readRanges(f, 2, n, no_echo);
      // 180 deg in front, both ends included (-90 .. +90 deg). On the Intel log this and not
      // 180/n deg per step makes straight walls straight (ICP-SLAM ATE 0.13 m against 1.9 m).
      s.scan.angle_min = -M_PI / 2.0;
      s.scan.angle_increment = M_PI / (n - 1);
      s.scan.range_min = 0.0;
      s.scan.range_max = no_echo;
      s.reference = poseAt(f, 2 + n, "x y theta");
      laser_odometry.push_back(poseAt(f, 5 + n, "odom_x odom_y odom_theta"));
      s.scan.stamp = f.number(8 + n, "ipc_timestamp");
      log.scans.push_back(s);
    } else if (kind == "ROBOTLASER1") {
      // ROBOTLASER1 type start_angle fov resolution max_range accuracy remission_mode n r1..rn
      //   m rem1..remm laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv fsd ssd
      //   turn_axis ipc_timestamp ipc_hostname logger_timestamp
      const double start = f.number(2, "start_angle"), fov = f.number(3, "field_of_view"), max_range = f.number(5, "maximum_range");
      const int n = f.count(8, "num_readings", 10000);
      if (n < 2) f.fail("fewer than 2 readings");
      const std::size_t rem = 9 + n;
      const int m = f.count(rem, "num_remissions", 10000);
      const std::size_t poses = rem + 1 + m;
      LogScan s;
      s.scan.ranges = readRanges(f, 9, n, std::min(no_echo, max_range > 0.0 ? max_range : no_echo));
      s.scan.angle_min = start;
      s.scan.angle_increment = fov / (n - 1);
      if (!(s.scan.angle_increment > 0.0)) f.fail("field_of_view must be > 0");
      s.scan.range_max = no_echo;
      const core::Pose2 laser = poseAt(f, poses, "laser_pose"), robot = poseAt(f, poses + 3, "robot_pose");
      s.scan.mount = compose(inverse(robot), laser);
      s.reference = robot;
      laser_odometry.push_back(robot);
      s.scan.stamp = f.number(poses + 11, "ipc_timestamp");
      log.scans.push_back(s);
    }
  }
  if (log.scans.empty()) throw std::runtime_error(path + ": no FLASER or ROBOTLASER1 line (not a CARMEN log?)");
  log.odom_lines = static_cast<int>(odom.size());
  // Real logs interleave messages a few ms out of order (the Intel log: 1 ODOM line in 10).
  std::stable_sort(odom.begin(), odom.end(), [](const OdomSample& a, const OdomSample& b) { return a.stamp < b.stamp; });
  for (std::size_t i = 0; i < log.scans.size(); ++i)
    log.scans[i].odometry = odom.empty() ? laser_odometry[i] : odometryAt(odom, log.scans[i].scan.stamp);
  return log;
}

}  // namespace localization
}  // namespace amigobot_tracking
