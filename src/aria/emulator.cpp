#include "amigobot_tracking/aria/emulator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <stdexcept>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/core/robot/unicycle.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

}  // namespace

RobotEmulator::RobotEmulator(EmulatorOptions options)
    : options_(std::move(options)), rng_(options_.seed), pose_(options_.initial_pose) {
  const std::string error = options_.validate();
  if (!error.empty()) throw std::invalid_argument("emulator: " + error);
  base_.emplace(options_.robot.dynamics, options_.robot.halfTrack());
  close();
  counters_.closes = 0;
  if (options_.left_open_at_baud > 0) {
    open_ = true;  // SIPs from the start; the watchdog has already stopped the wheels
    baud_ = options_.left_open_at_baud;
  }
}

void RobotEmulator::close() {
  // CLOSE reverts the settings to the FLASH defaults and stops everything.
  open_ = false;
  baud_ = kFlashBaud;
  polling_.clear();
  ticks_mm_ = options_.ticks_mm;
  rev_count_ = options_.rev_count;
  drift_factor_ = 0;
  sync_stage_ = 0;
  motors_ = false;
  sonar_on_ = true;
  setTarget(0.0, 0.0);
  max_v_ = options_.robot.dynamics.max_velocity;
  max_w_ = options_.robot.dynamics.max_rot_velocity;
  accel_ = options_.robot.dynamics.trans_accel;
  decel_ = options_.robot.dynamics.trans_decel;
  rot_accel_ = options_.robot.dynamics.rot_accel;
  rot_decel_ = options_.robot.dynamics.rot_decel;
  syncLimits();
  watchdog_tripped_ = false;
  ++counters_.closes;
}

void RobotEmulator::syncLimits() {
  // The robot description's base (cycle, latency, ceilings) with the ramps SETA / SETRA set
  // live; SETV / SETRV cut the setpoint in setTarget.
  core::ActuatorLimits l = options_.robot.dynamics;
  l.trans_accel = accel_;
  l.trans_decel = decel_;
  l.rot_accel = rot_accel_;
  l.rot_decel = rot_decel_;
  base_->setLimits(l);
}

void RobotEmulator::clientDisconnected() {
  if (options_.simulator_mode && open_) close();
}

void RobotEmulator::setTarget(double v, double w) {
  requested_v_ = v;
  requested_w_ = w;
  target_v_ = std::clamp(v, -max_v_, max_v_);
  target_w_ = std::clamp(w, -max_w_, max_w_);
}

std::vector<std::uint8_t> RobotEmulator::handle(const Packet& packet, double now) {
  ++counters_.packets;
  // Kinematics only: a SIP falling due now is left to the next advance() (the server calls
  // it right after the packets it read), not made here and lost with the reply.
  stepTo(now);
  if (deaf_) {
    ++counters_.unheard_packets;
    return {};
  }
  const std::optional<int> arg = intArgument(packet);
  const int value = arg.value_or(0);
  if (!open_) {
    // SYNC1 and OPEN share byte 1 and SYNC2 and CLOSE byte 2: the handshake stage tells
    // them apart. Out of sequence, the firmware restarts at SYNC0.
    switch (packet.type) {
      case kSync0:
        sync_stage_ = 1;
        return encodePacket(kSync0, {});
      case kSync1:
        if (sync_stage_ == 3) {
          open_ = true;
          sync_stage_ = 0;
          motors_ = options_.simulator_mode;
          ++counters_.opens;
          last_command_ = now;
          next_sip_ = now;
          return {};
        }
        if (sync_stage_ == 1) {
          sync_stage_ = 2;
          return encodePacket(kSync1, {});
        }
        sync_stage_ = 0;
        return {};
      case kSync2:
        if (sync_stage_ == 2) {
          sync_stage_ = 3;
          return encodeSync2({options_.name, "Pioneer", options_.robot.model});
        }
        sync_stage_ = 0;
        return {};
      default:
        ++counters_.commands_while_closed;
        return {};
    }
  }
  last_command_ = now;
  watchdog_tripped_ = false;  // commands resumed: back to the last setpoints
  const double b = options_.robot.halfTrack();
  switch (static_cast<Command>(packet.type)) {
    case Command::kPulse:  // SYNC0 (same byte) while open is a PULSE
    case Command::kOpen:
      break;
    case Command::kClose:
      close();
      break;
    case Command::kEnable:
      motors_ = value != 0;
      setTarget(0.0, 0.0);
      break;
    case Command::kSetA:
      if (value > 0) accel_ = value * 1e-3;
      if (value < 0) decel_ = -value * 1e-3;
      syncLimits();
      break;
    case Command::kSetV:
      if (value > 0) max_v_ = std::min(value * 1e-3, options_.robot.dynamics.max_velocity);
      break;
    case Command::kSetRV:
      if (value > 0) max_w_ = std::min(value * kDegToRad, options_.robot.dynamics.max_rot_velocity);
      break;
    case Command::kSetRA:
      if (value > 0) rot_accel_ = value * kDegToRad;
      if (value < 0) rot_decel_ = -value * kDegToRad;
      syncLimits();
      break;
    case Command::kSetO:
      odo_x_mm_ = odo_y_mm_ = odo_th_ = 0.0;
      break;
    case Command::kVel:
      setTarget(value * 1e-3, requested_w_);
      journal(now, "VEL");
      break;
    case Command::kRVel:
    case Command::kRotate:
      setTarget(requested_v_, value * kDegToRad);
      journal(now, "RVEL");
      break;
    case Command::kVel2: {
      int left = 0, right = 0;
      unpackVel2(value, left, right);
      const double l = left * options_.robot.vel2_divisor * 1e-3;
      const double r = right * options_.robot.vel2_divisor * 1e-3;
      setTarget(0.5 * (l + r), 0.5 * (r - l) / b);
      journal(now, "VEL2");
      break;
    }
    case Command::kStop:
      setTarget(0.0, 0.0);
      journal(now, "STOP");
      break;
    case Command::kEStop:
      setTarget(0.0, 0.0);
      v_ = w_ = 0.0;
      journal(now, "ESTOP");
      break;
    case Command::kSonar:
      sonar_on_ = value != 0;
      break;
    case Command::kPolling: {
      // Transducer numbers from 1; an unknown one rejects the whole order.
      const std::optional<std::string> order = stringArgument(packet);
      std::vector<std::size_t> polling;
      for (char c : order.value_or("")) polling.push_back(static_cast<std::uint8_t>(c) - std::size_t{1});
      const bool valid = order && std::all_of(polling.begin(), polling.end(), [&](std::size_t i) {
        return i < options_.robot.sonars.size();
      });
      if (valid) {
        polling_ = polling;
        next_sonar_ = 0;
      } else {
        ++counters_.unknown_commands;
      }
      break;
    }
    case Command::kTicksMM:
      if (value > 0) ticks_mm_ = value;
      break;
    case Command::kRevCount:
      if (value > 0) rev_count_ = value;
      break;
    case Command::kDriftFactor:
      drift_factor_ = value;
      break;
    case Command::kHostBaud:
      // The reply to this command, if any, still goes out at the old rate: none is sent.
      if (options_.simulator_mode || value < 0 || value > 4) {
        ++counters_.unknown_commands;
      } else {
        baud_ = kHostBauds[value];
      }
      break;
    case Command::kEncoder: {
      // ENCODER 1: one encoder packet now (int32 left, int32 right, LE). 2 (continuous) and
      // 0 (stop) are not emulated: nothing streams.
      if (value != 1) break;
      std::vector<std::uint8_t> payload;
      for (const double ticks : {left_ticks_, right_ticks_}) {
        const auto t = static_cast<std::uint32_t>(static_cast<std::int32_t>(std::fmod(std::round(ticks), 2147483648.0)));
        for (int k = 0; k < 4; ++k) payload.push_back(static_cast<std::uint8_t>(t >> (8 * k)));
      }
      return encodePacket(kEncoderPacType, payload);
    }
    case Command::kConfig: {
      ConfigPac c;
      c.robot_type = "Pioneer";
      c.subtype = options_.robot.model;
      c.serial = "EMU0001";
      c.rot_vel_top = static_cast<std::uint16_t>(std::lround(options_.robot.dynamics.max_rot_velocity / kDegToRad));
      c.trans_vel_top = static_cast<std::uint16_t>(std::lround(options_.robot.dynamics.max_velocity * 1e3));
      c.rot_acc_top = c.trans_acc_top = 0;
      c.name = options_.name;
      c.sip_cycle_ms = static_cast<std::uint8_t>(std::lround(options_.robot.dynamics.cycle * 1e3));
      c.watchdog = static_cast<std::uint16_t>(std::lround(options_.robot.watchdog * 1e3));
      c.rot_vel_max = static_cast<std::uint16_t>(std::lround(max_w_ / kDegToRad));
      c.trans_vel_max = static_cast<std::uint16_t>(std::lround(max_v_ * 1e3));
      c.rot_acc = static_cast<std::uint16_t>(std::lround(rot_accel_ / kDegToRad));
      c.rot_decel = static_cast<std::uint16_t>(std::lround(rot_decel_ / kDegToRad));
      c.trans_acc = static_cast<std::uint16_t>(std::lround(accel_ * 1e3));
      c.trans_decel = static_cast<std::uint16_t>(std::lround(decel_ * 1e3));
      c.front_sonar = 1;
      c.host_baud = static_cast<std::uint8_t>(std::max(0, hostBaudIndex(baud_)));
      c.auto_baud = options_.simulator_mode ? 0 : 2;  // 2: the firmware can switch (HOSTBAUD)
      c.firmware_version = "amigobot_emulator";
      c.ticks_mm = static_cast<std::uint16_t>(ticks_mm_);
      c.rev_count = static_cast<std::uint16_t>(rev_count_);
      c.drift_factor = static_cast<std::int16_t>(drift_factor_);
      return encodeConfigPac(c);
    }
    default:
      ++counters_.unknown_commands;
      break;
  }
  return {};
}

void RobotEmulator::journal(double now, const char* command) const {
  if (!command_log_) return;
  *command_log_ << std::fixed << std::setprecision(4) << now << ' ' << command << ' ' << std::setprecision(6)
                << requested_v_ << ' ' << requested_w_ << std::endl;
}

void RobotEmulator::checkWatchdog(double now) {
  if (!open_ || watchdog_tripped_ || now - last_command_ <= options_.robot.watchdog) return;
  watchdog_tripped_ = true;
  ++counters_.watchdog_trips;
  if (options_.simulator_mode) {
    std::fprintf(stderr, "amigobot_emulator: watchdog: no command for %.1f s (simulator: warning only)\n",
                 now - last_command_);
  }
}

void RobotEmulator::stepPhysics(double dt) {
  const bool watchdog_stop = watchdog_tripped_ && !options_.simulator_mode;
  const bool drive = motors_ && !watchdog_stop;
  const double tv = drive ? target_v_ : 0.0;
  const double tw = drive ? target_w_ : 0.0;
  // The firmware's cycle, latency, ramps and wheel-speed limit: the one actuator model.
  const core::Twist2 mean = base_->step({tv, tw}, dt);
  v_ = base_->velocity().v;
  w_ = base_->velocity().omega;
  pose_ = core::integrateUnicycle(pose_, mean, dt);
  const double b = options_.robot.halfTrack();
  // The firmware's odometry integrates its (noisy) wheel speeds in its own frame, counting
  // encoder ticks with its working calibration: a TicksMM above the encoders' true one
  // shrinks every distance, a larger RevCount every turn, DriftFactor scales the right wheel.
  const double distance_scale = static_cast<double>(options_.ticks_mm) / ticks_mm_;
  const double turn_scale = static_cast<double>(options_.rev_count) / rev_count_;
  double left = mean.v - b * mean.omega, right = (mean.v + b * mean.omega) * (1.0 + drift_factor_ / 8192.0);
  if (options_.odometry_noise > 0.0) {
    std::normal_distribution<double> noise(0.0, options_.odometry_noise);
    left *= 1.0 + noise(rng_);
    right *= 1.0 + noise(rng_);
  }
  const core::Pose2 odo = core::integrateUnicycle({odo_x_mm_ * 1e-3, odo_y_mm_ * 1e-3, odo_th_},
                                                  {0.5 * (left + right) * distance_scale,
                                                   0.5 * (right - left) / b * turn_scale},
                                                  dt);
  left_ticks_ += left * dt * 1e3 * options_.ticks_mm;
  right_ticks_ += right * dt * 1e3 * options_.ticks_mm;
  odo_x_mm_ = odo.x * 1e3;
  odo_y_mm_ = odo.y * 1e3;
  odo_th_ = odo.theta;
}

void RobotEmulator::teleport(const core::Pose2& pose) {
  if (!pose.isFinite()) throw std::invalid_argument("emulator: teleport to a non-finite pose");
  pose_ = {pose.x, pose.y, std::remainder(pose.theta, 2.0 * M_PI)};
}

void RobotEmulator::stepTo(double now) {
  if (teleports_) {
    if (const std::optional<core::Pose2> pose = teleports_->take()) teleport(*pose);
    deaf_ = teleports_->deaf();
  }
  if (last_time_ < 0.0) last_time_ = now;
  // The watchdog is checked every physics step, so a long advance() stops the robot at the
  // right moment rather than at the end.
  while (last_time_ < now) {
    checkWatchdog(last_time_);
    const double dt = std::min(options_.physics_step, now - last_time_);
    stepPhysics(dt);
    last_time_ += dt;
  }
  checkWatchdog(now);
}

std::vector<std::uint8_t> RobotEmulator::advance(double now) {
  stepTo(now);
  if (!open_) return {};
  if (now < next_sip_) return {};
  next_sip_ += options_.robot.dynamics.cycle;
  if (next_sip_ <= now) next_sip_ = now + options_.robot.dynamics.cycle;  // fell behind: do not burst
  ++counters_.sips_sent;
  return makeSip();
}

EmulatorStatus RobotEmulator::status(double now) const {
  return {now, pose_, v_, w_, motors_, open_, watchdog_tripped_};
}

}  // namespace aria
}  // namespace amigobot_tracking
