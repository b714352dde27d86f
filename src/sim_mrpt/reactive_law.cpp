#include "amigobot_tracking/sim_mrpt/reactive_law.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/Clock.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>
#include <mrpt/nav/reactive/CRobot2NavInterface.h>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/world/raycast.h"

namespace amigobot_tracking {
namespace sim_mrpt {
namespace {

// MRPT stamps with 0 mean "invalid": simulated time t is shown to MRPT as kEpoch + t.
constexpr double kEpoch = 1.0e9;  // [s] since 1970 (2001)

// MRPT's process-wide clock follows the simulation while a law lives; restored when the last
// live law goes. Monte Carlo runs laws on several threads at once: the first saves the clock
// and the last restores it (a per-law save/restore let a later law put back "Simulated").
// The navigator decides from getNavigationTime(), not from this clock: a batch of MRPT runs
// gives the same figures on 1 or 2 jobs (test_sim_mrpt_reactive).
class SimulatedClock {
 public:
  SimulatedClock() {
    std::lock_guard<std::mutex> lock(mutex());
    if (users()++ == 0) {
      previous() = mrpt::Clock::getActiveClock();
      mrpt::Clock::setSimulatedTime(mrpt::Clock::fromDouble(kEpoch));
      mrpt::Clock::setActiveClock(mrpt::Clock::Simulated);
    }
  }
  ~SimulatedClock() {
    std::lock_guard<std::mutex> lock(mutex());
    if (--users() == 0) mrpt::Clock::setActiveClock(previous());
  }
  SimulatedClock(const SimulatedClock&) = delete;
  SimulatedClock& operator=(const SimulatedClock&) = delete;
  static void set(double t) {
    std::lock_guard<std::mutex> lock(mutex());
    mrpt::Clock::setSimulatedTime(mrpt::Clock::fromDouble(kEpoch + t));
  }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static int& users() {
    static int n = 0;
    return n;
  }
  static mrpt::Clock::Source& previous() {
    static mrpt::Clock::Source source = mrpt::Clock::Realtime;
    return source;
  }
};

// The simulator's unicycle as MRPT's robot: pose and time from the closed loop, a laser
// ray-cast against the disks, commands saturated by the diamond and held until the next one.
class UnicycleRobot : public mrpt::nav::CRobot2NavInterface {
 public:
  UnicycleRobot(const core::DiamondSet& diamond, const ReactiveLawOptions& options)
      : diamond_(diamond), options_(options) {
    setMinLoggingLevel(mrpt::system::LVL_ERROR);
  }

  void setState(double t, const core::Pose2& pose, const std::vector<core::Disk>& obstacles) {
    t_ = t;
    pose_ = pose;
    obstacles_ = &obstacles;
  }
  const core::Twist2& command() const { return command_; }
  const core::Twist2& requested() const { return requested_; }

  bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velocity,
                               mrpt::system::TTimeStamp& stamp, mrpt::math::TPose2D& odometry,
                               std::string& frame_id) override {
    pose = mrpt::math::TPose2D(pose_.x, pose_.y, pose_.theta);
    velocity = mrpt::math::TTwist2D(command_.v * std::cos(pose_.theta), command_.v * std::sin(pose_.theta),
                                    command_.omega);
    stamp = mrpt::Clock::fromDouble(kEpoch + t_);
    odometry = pose;  // ground truth: odometry and localisation agree
    frame_id = "map";
    return true;
  }

  bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& command) override {
    const auto* drive = dynamic_cast<const mrpt::kinematics::CVehicleVelCmd_DiffDriven*>(&command);
    if (!drive) return false;
    requested_ = {drive->lin_vel, drive->ang_vel};
    const auto saturated = diamond_.saturate(requested_);  // (12): nothing leaves the diamond
    if (!saturated) {
      command_ = requested_ = core::Twist2();
      return false;
    }
    command_ = *saturated;
    return true;
  }
  bool stop(bool /*emergency*/) override {
    command_ = requested_ = core::Twist2();
    return true;
  }
  mrpt::kinematics::CVehicleVelCmd::Ptr getEmergencyStopCmd() override { return getStopCmd(); }
  mrpt::kinematics::CVehicleVelCmd::Ptr getStopCmd() override {
    return std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
  }

  // The disks as a 360-degree laser at the robot centre sees them: one point per returning
  // beam, in the robot frame.
  bool senseObstacles(mrpt::maps::CSimplePointsMap& points, mrpt::system::TTimeStamp& stamp) override {
    points.clear();
    stamp = mrpt::Clock::fromDouble(kEpoch + t_);
    core::ScanGeometry geometry;
    geometry.angle_increment = 2.0 * M_PI / options_.beams;
    geometry.angle_min = -M_PI;
    geometry.range_min = 0.01;
    geometry.range_max = options_.range_max;
    const std::vector<float> ranges = world::raycastScan(pose_, world::disksOnly(*obstacles_), geometry, options_.beams);
    for (size_t i = 0; i < ranges.size(); ++i) {
      double range = ranges[i];
      if (std::isinf(range) && range < 0.0) range = geometry.range_min;  // closer than range_min: touching
      if (!std::isfinite(range)) continue;
      const double angle = geometry.angle_min + geometry.angle_increment * static_cast<double>(i);
      points.insertPoint(static_cast<float>(range * std::cos(angle)), static_cast<float>(range * std::sin(angle)),
                         0.0f);
    }
    return true;
  }

  double getNavigationTime() override { return t_; }
  void resetNavigationTimer() override {}

 private:
  core::DiamondSet diamond_;
  ReactiveLawOptions options_;
  double t_ = 0.0;
  core::Pose2 pose_;
  const std::vector<core::Disk>* obstacles_ = nullptr;
  core::Twist2 command_, requested_;
};

// Where the PTGs' collision grids are cached: one folder per configuration text.
std::string cacheFolder(const std::string& ini) {
  std::ostringstream name;
  name << std::hex << std::hash<std::string>{}(ini);
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "amigobot_mrpt_ptg" / name.str();
  std::error_code ignored;
  std::filesystem::create_directories(folder, ignored);
  return folder.string();
}

// The navigator without its delay statistics (printed on destruction, once per run otherwise).
class QuietNavigator : public mrpt::nav::CReactiveNavigationSystem {
 public:
  explicit QuietNavigator(mrpt::nav::CRobot2NavInterface& robot)
      : CReactiveNavigationSystem(robot, false /*console*/, false /*log file*/) {
    m_timlog_delays.enable(false);
    setMinLoggingLevel(mrpt::system::LVL_ERROR);
  }
};

class ReactiveLaw : public core::ControlLaw {
 public:
  ReactiveLaw(const core::ControllerConfig& config, const ReactiveLawOptions& options)
      : config_(config),
        options_(options),
        diamond_(config.v_max, config.w_max),
        robot_(diamond_, options),
        navigator_(robot_) {
    const std::string ini = reactiveConfigText(config, options);
    mrpt::config::CConfigFileMemory file(ini);
    navigator_.loadConfigFile(file);
    // Not read from the file by MRPT 2.5 (default "."): set after loading.
    navigator_.params_abstract_ptg_navigator.ptg_cache_files_directory = cacheFolder(ini);
    navigator_.initialize();
  }

  core::ControllerOutput step(double t, const core::PoseSample& robot, const core::TargetSample& target,
                              const std::vector<core::Disk>& obstacles) override {
    core::ControllerOutput out;
    out.t = t;
    if (!std::isfinite(t) || !robot.pose.isFinite() || !target.position.allFinite() || (started_ && t < last_t_)) {
      out.error = "inputs not usable (non-finite, or time went backwards)";
      return out;
    }
    out.valid = true;
    out.p_r = core::offsetPoint(robot.pose, config_.offset);
    out.p_d = target.position;
    out.e = out.p_d - out.p_r;
    if (!started_ || t >= next_update_ - 1e-9) {
      if (!started_ && options_.prime_scores) primeScores(t, robot.pose, obstacles);
      navigate(t, robot.pose, target.position, obstacles);
      next_update_ = started_ ? next_update_ + options_.period : t + options_.period;
      if (next_update_ <= t) next_update_ = t + options_.period;  // a long step skipped periods
      started_ = true;
    }
    last_t_ = t;
    out.u = robot_.command();
    out.u_d = robot_.requested();
    out.active.saturated = out.u.v != out.u_d.v || out.u.omega != out.u_d.omega;
    out.min_clearance = core::clearance(out.p_r, config_.effectiveRadius(), obstacles);
    for (const core::Disk& o : obstacles)
      if ((out.p_r - o.center).norm() - config_.effectiveRadius() - o.radius <= config_.delta) ++out.detected_obstacles;
    out.active.avoiding = out.detected_obstacles > 0;
    return out;
  }

  const core::DiamondSet& diamond() const override { return diamond_; }
  // MRPT's navigator cannot be copied: a copy is a fresh law with the same configuration.
  std::unique_ptr<core::ControlLaw> clone() const override { return std::make_unique<ReactiveLaw>(config_, options_); }
  std::string name() const override { return "mrpt_reactive"; }
  // The navigator's state is MRPT's: a reset re-targets at the next step as a fresh law does.
  void reset() override {
    started_ = false;
    last_t_ = next_update_ = 0.0;
  }
  // The navigator is configured once (its limits and robot shape are in its INI text).
  void setConfig(const core::ControllerConfig& config) override { (void)config; }
  const core::ControllerConfig& config() const override { return config_; }

 private:
  // Re-target at the target's latest position and run one navigation step.
  void navigate(double t, const core::Pose2& pose, const Eigen::Vector2d& target,
                const std::vector<core::Disk>& obstacles) {
    SimulatedClock::set(t);
    robot_.setState(t, pose, obstacles);
    mrpt::nav::CAbstractNavigator::TNavigationParams params;
    params.target.target_coords = mrpt::math::TPose2D(target.x(), target.y(), 0.0);
    params.target.targetAllowedDistance = static_cast<float>(config_.offset);  // p_r at the target
    params.target.targetIsRelative = false;
    navigator_.navigate(&params);
    navigator_.navigationStep();
    failOnNavigatorError(t);
  }

  // MRPT 2.5 compiles its score formulas (exprtk) from the variables of the first candidate of
  // its first decision, the candidate of PTG 0; a PTG whose domain misses the target has no
  // variables, so a target outside PTG 0's domain (a start facing away from it, close) fails
  // the compilation ("ERR201 - Undefined symbol: 'target_d_norm'") at every step and the robot
  // never moves. One decision on a point straight ahead (on PTG 0's straight path, always in its
  // domain) compiles them once and for all; the real decision follows at the same instant.
  void primeScores(double t, const core::Pose2& pose, const std::vector<core::Disk>& obstacles) {
    const double ahead = 0.5 * options_.ref_distance;
    navigate(t, pose, pose.position() + ahead * Eigen::Vector2d(std::cos(pose.theta), std::sin(pose.theta)), obstacles);
  }

  // The navigator catches its own exceptions and stops the robot: a run on after that would
  // score a robot that never moved, so the error ends the run, naming MRPT's reason. MRPT 2.5
  // restores the NAVIGATING state at the end of the step, so the reason it recorded (kept until
  // the next navigate()) is what shows the error, not the state.
  void failOnNavigatorError(double t) const {
    if (navigator_.getCurrentState() != mrpt::nav::CAbstractNavigator::NAV_ERROR &&
        navigator_.getErrorReason().error_code == mrpt::nav::CAbstractNavigator::ERR_NONE)
      return;
    std::ostringstream why;
    why << "mrpt_reactive: MRPT's navigator failed at t = " << t
        << " s: " << navigator_.getErrorReason().error_msg;
    throw std::runtime_error(why.str());
  }

  core::ControllerConfig config_;
  ReactiveLawOptions options_;
  core::DiamondSet diamond_;
  SimulatedClock clock_;  // before the navigator: MRPT reads the clock from its constructor on
  UnicycleRobot robot_;
  QuietNavigator navigator_;
  bool started_ = false;
  double last_t_ = 0.0, next_update_ = 0.0;
};

}  // namespace

std::unique_ptr<core::ControlLaw> makeReactiveLaw(const core::LawSetup& setup, const ReactiveLawOptions& options) {
  if (!(options.period > 0.0) || options.beams < 8 || !(options.range_max > 0.0) || !(options.ref_distance > 0.0))
    throw std::invalid_argument("sim_mrpt: period, ref_distance and range_max must be > 0 and beams >= 8");
  return std::make_unique<ReactiveLaw>(setup.controller, options);
}

core::LawFactory reactiveLawFactory(const ReactiveLawOptions& options) {
  return [options](const core::LawSetup& setup) { return makeReactiveLaw(setup, options); };
}

core::LawFactory provideReactiveLaw(const ReactiveLawOptions& options) {
  return core::provideLaw("mrpt_reactive", reactiveLawFactory(options));
}

}  // namespace sim_mrpt
}  // namespace amigobot_tracking
