#include "amigobot_tracking/aria/client.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/core/support/error_text.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr int kPollMs = 20;
constexpr double kInterByteTimeout = 0.1;  // [s] ARIA drops a partial packet after 100 ms
constexpr double kEnableRetry = 1.0;       // [s] ENABLE re-sent while the SIP disagrees

double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }
double seconds(std::chrono::steady_clock::time_point t) { return seconds(t.time_since_epoch()); }

void defaultLog(LogLevel level, const std::string& text) {
  static const char* names[] = {"debug", "info", "warn", "error"};
  if (level == LogLevel::kDebug) return;
  std::fprintf(stderr, "[aria %s] %s\n", names[static_cast<int>(level)], text.c_str());
}

}  // namespace

std::string linkStateName(LinkState state) {
  switch (state) {
    case LinkState::kStopped: return "stopped";
    case LinkState::kConnecting: return "connecting";
    case LinkState::kConnected: return "connected";
    case LinkState::kWaitingToReconnect: return "waiting to reconnect";
  }
  return "unknown";
}

AriaClient::AriaClient(ClientConfig config, LogFunction log)
    : config_(std::move(config)),
      log_(log ? std::move(log) : LogFunction(defaultLog)),
      diamond_(1.0, 1.0),
      parser_(static_cast<std::size_t>(std::clamp(config_.max_packet_count, 3, 255))),
      odometry_(config_.robot),
      ack_watch_(kAckProbePeriod, config_.command_ack_timeout, kAckProbeSupportWait) {
  const std::string error = config_.validate();
  if (!error.empty()) throw std::invalid_argument("AriaClient: " + error);
  diamond_ = config_.diamond();
  sonar_ranges_.assign(config_.robot.sonars.size(), std::nan(""));
}

AriaClient::~AriaClient() { stop(); }

void AriaClient::start() {
  if (thread_.joinable()) return;
  stop_requested_ = false;
  thread_ = std::thread([this] { run(); });
}

void AriaClient::stop() {
  {
    // Under the wait's mutex, so a back-off sleep cannot miss the wake-up.
    std::lock_guard<std::mutex> lock(wake_mutex_);
    stop_requested_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void AriaClient::setVelocity(const core::Twist2& twist) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!twist.isFinite()) {
    ++status_.non_finite_requests;
    requested_ = {};  // a broken request stops the robot rather than keeping the old one
  } else {
    requested_ = twist;
  }
  requested_at_ = Clock::now();
  have_request_ = true;
}

void AriaClient::requestMotors(bool enabled) {
  std::lock_guard<std::mutex> lock(mutex_);
  status_.motors_requested = enabled;
  motors_request_pending_ = true;
}

void AriaClient::resetOdometry(const core::Pose2& pose) {
  std::lock_guard<std::mutex> lock(mutex_);
  odometry_reset_ = pose;
}

ClientStatus AriaClient::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  ClientStatus copy = status_;
  copy.parser = parser_.stats();
  return copy;
}

void AriaClient::log(LogLevel level, const std::string& text) { log_(level, text); }

void AriaClient::setLink(LinkState state) {
  std::lock_guard<std::mutex> lock(mutex_);
  status_.link = state;
}

bool AriaClient::sleepUnlessStopped(double s) {
  std::unique_lock<std::mutex> lock(wake_mutex_);
  wake_.wait_for(lock, std::chrono::duration<double>(s), [this] { return stop_requested_.load(); });
  return !stop_requested_;
}

void AriaClient::send(const std::vector<std::uint8_t>& bytes) {
  transport_->write(bytes);
  std::lock_guard<std::mutex> lock(mutex_);
  status_.bytes_sent += bytes.size();
}

void AriaClient::setLineBaud(int baud) {
  transport_->setBaud(baud);
  std::lock_guard<std::mutex> lock(mutex_);
  parser_.reset();
  status_.baud = transport_->baud();
}

void AriaClient::run() {
  double backoff = config_.reconnect_delay_min;
  while (!stop_requested_) {
    setLink(LinkState::kConnecting);
    try {
      if (connect()) {
        backoff = config_.reconnect_delay_min;
        serve();
      }
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      status_.last_error = core::libraryMessage(e.what());
    }
    if (transport_) transport_->close();
    if (stop_requested_) break;
    std::string error;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      status_.link = LinkState::kWaitingToReconnect;
      status_.robot.reset();
      error = status_.last_error;
    }
    char delay[32];
    std::snprintf(delay, sizeof(delay), "%.1f", backoff);
    // An ERROR naming the port and the reason on every failed attempt: the back-off (at most
    // reconnect_delay_max apart) is its throttle.
    const std::string where = transport_ ? transport_->describe() : "(no port)";
    if (error.rfind(where + ": ", 0) == 0) error.erase(0, where.size() + 2);
    log(LogLevel::kError, "robot link " + where + " down: " + error + "; reconnecting in " + delay + " s");
    sleepUnlessStopped(backoff);
    backoff = std::min(2.0 * backoff, config_.reconnect_delay_max);
  }
  setLink(LinkState::kStopped);
}

void AriaClient::pump(int timeout_ms) {
  std::uint8_t buffer[512];
  const std::size_t n = transport_->read(buffer, sizeof(buffer), timeout_ms);
  const auto now = Clock::now();
  if (n > 0) {
    last_rx_ = now;
    std::lock_guard<std::mutex> lock(mutex_);  // status() copies the parser's counters
    parser_.feed(buffer, n);
    status_.bytes_received += n;
  } else if (parser_.hasPartial() && seconds(now - last_rx_) > kInterByteTimeout) {
    std::lock_guard<std::mutex> lock(mutex_);
    parser_.expirePartial();
  }
}

bool AriaClient::nextPacket(Packet& packet) {
  std::lock_guard<std::mutex> lock(mutex_);
  return parser_.next(packet);
}

bool AriaClient::receiveFor(double duration, const std::function<bool(const Packet&)>& on_packet) {
  const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(duration));
  Packet packet;
  while (Clock::now() < until && !stop_requested_) {
    while (nextPacket(packet)) {
      if (on_packet(packet)) return true;
    }
    pump(kPollMs);
  }
  return false;
}

bool AriaClient::connect() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    parser_.reset();
  }
  transport_ = makeTransport(config_.port, config_.baud);
  log(LogLevel::kInfo, "connecting to the robot over " + transport_->describe());
  transport_->open();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_.baud = transport_->baud();
  }
  const std::optional<RobotIdentity> identity = synchronise();
  if (!identity) return false;  // stop requested
  if (identity->subclass != config_.robot.model) {
    log(LogLevel::kWarn, "robot reports subclass '" + identity->subclass + "' but the parameters are for '" +
                             config_.robot.model + "'");
  }
  const std::optional<ConfigPac> config = openRobot();
  if (stop_requested_) {
    shutdownRobot();  // stopped halfway: do not leave the robot open
    return false;
  }

  odometry_.relink();
  sent_.reset();
  sip_times_.clear();
  last_sip_ = last_rx_ = Clock::now();
  ack_watch_.connected(seconds(last_sip_));
  last_motion_sent_ = last_enable_sent_ = Clock::time_point{};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_.identity = identity;
    status_.config = config;
    ++status_.connections;
    status_.last_error.clear();
    if (config_.enable_motors) status_.motors_requested = true;
    motors_request_pending_ = true;  // re-assert the requested motor state on every connection
    status_.link = LinkState::kConnected;
  }
  log(LogLevel::kInfo, "connected to '" + identity->name + "' (" + identity->robot_class + " " + identity->subclass +
                           ") over " + transport_->describe());
  return true;
}

void AriaClient::serve() {
  Packet packet;
  while (!stop_requested_) {
    pump(kPollMs);
    while (nextPacket(packet)) handlePacket(packet);
    const auto now = Clock::now();
    if (seconds(now - last_sip_) > config_.link_timeout) {
      throw std::runtime_error("no SIP for " + std::to_string(seconds(now - last_sip_)).substr(0, 4) + " s");
    }
    updateCommand(now);
    probeAcknowledgement(now);
  }
  shutdownRobot();
}

void AriaClient::handlePacket(const Packet& packet) {
  if (isSipType(packet.type)) {
    std::string error;
    const std::optional<Sip> sip = decodeSip(packet, &error);
    if (sip) {
      handleSip(*sip);
    } else {
      log(LogLevel::kWarn, error);
    }
  } else if (packet.type == kConfigPacType) {
    std::optional<ConfigPac> config = decodeConfigPac(packet);
    std::lock_guard<std::mutex> lock(mutex_);
    if (config) status_.config = std::move(config);
  } else if (packet.type == kEncoderPacType) {
    ack_watch_.answered(seconds(Clock::now()));
    std::lock_guard<std::mutex> lock(mutex_);
    ++status_.probes_answered;
  }
}


void AriaClient::handleSip(const Sip& sip) {
  const auto now = Clock::now();
  last_sip_ = now;
  ack_watch_.sipArrived(seconds(now));
  sip_times_.push_back(now);
  sip_times_.erase(sip_times_.begin(),
                   std::find_if(sip_times_.begin(), sip_times_.end(),
                                [&](Clock::time_point t) { return seconds(now - t) <= 1.0; }));
  RobotState state;
  state.stamp = seconds(now.time_since_epoch());
  state.odometry = odometry_.update(sip);
  state.battery_voltage = 0.1 * (sip.battery_x10 ? *sip.battery_x10 : sip.battery);
  state.motors_enabled = sip.motorsEnabled();
  state.left_stall = sip.leftStall();
  state.right_stall = sip.rightStall();
  state.sonar_updated.assign(sonar_ranges_.size(), false);
  for (const auto& reading : sip.sonars) {
    if (reading.index >= sonar_ranges_.size()) continue;  // a transducer the model does not have
    sonar_ranges_[reading.index] = sonarRange(reading, config_.robot);
    state.sonar_updated[reading.index] = true;
  }
  state.sonar_ranges = sonar_ranges_;
  state.sip = sip;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++status_.sips;
    const double span = seconds(sip_times_.back() - sip_times_.front());
    status_.sip_rate = span > 0.0 ? static_cast<double>(sip_times_.size() - 1) / span : 0.0;
    status_.robot = state;
  }
  if (sip_callback_) sip_callback_(state);
}

void AriaClient::updateCommand(Clock::time_point now) {
  applyPendingLimits();
  core::Twist2 desired;
  bool motors = false;
  bool motors_pending = false;
  bool robot_motors = false;
  std::optional<core::Pose2> reset;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool fresh = have_request_ && (config_.command_timeout <= 0.0 ||
                                         seconds(now - requested_at_) <= config_.command_timeout);
    if (fresh) desired = requested_;
    motors = status_.motors_requested;
    motors_pending = motors_request_pending_;
    motors_request_pending_ = false;
    robot_motors = status_.robot && status_.robot->motors_enabled;
    reset.swap(odometry_reset_);
  }
  if (reset) odometry_.reset(*reset);
  // The robot's motor state follows the request; a simulator starts with motors on.
  if (motors_pending || (robot_motors != motors && seconds(now - last_enable_sent_) > kEnableRetry)) {
    send(commandPacket(Command::kEnable, motors ? 1 : 0));
    last_enable_sent_ = now;
  }
  std::optional<QuantizedCommand> q = quantizeCommand(desired, config_.command_mode, config_.robot, diamond_);
  if (!q) q = quantizeCommand({}, config_.command_mode, config_.robot, diamond_);
  const bool changed = !sent_ || sent_->first != q->first || sent_->second != q->second;
  const double since = seconds(now - last_motion_sent_);
  if (!((changed && since >= config_.min_command_interval) || since >= config_.command_refresh)) return;
  if (q->mode == CommandMode::kVel2) {
    send(vel2Packet(q->first, q->second));
  } else if (rotationFirst(sent_ ? sent_->twist : core::Twist2(), q->twist, diamond_)) {
    send(commandPacket(Command::kRVel, q->second));  // the robot never holds a pair outside the diamond
    send(commandPacket(Command::kVel, q->first));
  } else {
    send(commandPacket(Command::kVel, q->first));
    send(commandPacket(Command::kRVel, q->second));
  }
  sent_ = q;
  last_motion_sent_ = now;
  std::lock_guard<std::mutex> lock(mutex_);
  ++status_.commands_sent;
  status_.last_command = q;
}

void AriaClient::shutdownRobot() {
  try {
    if (config_.command_mode == CommandMode::kVel2) {
      send(vel2Packet(0, 0));
    } else {
      send(commandPacket(Command::kVel, 0));
      send(commandPacket(Command::kRVel, 0));
    }
    send(commandPacket(Command::kEnable, 0));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    send(commandPacket(Command::kClose, 1));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    log(LogLevel::kInfo, "robot stopped, motors disabled and connection closed");
  } catch (const std::exception& e) {
    log(LogLevel::kWarn, std::string("could not close the robot cleanly: ") + e.what());
  }
}

}  // namespace aria
}  // namespace amigobot_tracking
