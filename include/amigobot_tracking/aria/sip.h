// Robot-to-client packets: the standard SIP (0x32/0x33), the SYNC2 reply and CONFIGpac
// (0x20). Decoders keep the robot's raw units; conversion to SI happens in odometry.h and
// the client with the robot's RobotParams. Encoders serve the emulator and the tests.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "amigobot_tracking/aria/packet.h"

namespace amigobot_tracking {
namespace aria {

struct SonarReading {
  std::uint8_t index = 0;
  std::uint16_t range = 0;  // raw; mm = range * RangeConvFactor
};

// Flag bits of the SIP FLAGS word.
constexpr std::uint16_t kFlagMotorsEnabled = 0x0001;
constexpr std::uint16_t kFlagSonarArrays = 0x001E;

struct Sip {
  std::uint8_t type = 0x32;      // 0x32 stopped, 0x33 moving
  std::uint16_t x = 0;           // XPOS masked to 15 bits
  std::uint16_t y = 0;           // YPOS masked to 15 bits
  std::int16_t theta = 0;        // THPOS, AngleConvFactor rad per unit
  std::int16_t left_vel = 0;     // VelConvFactor mm/s per unit
  std::int16_t right_vel = 0;
  std::uint8_t battery = 0;      // 0.1 V
  std::uint16_t stall_bumpers = 0;  // low byte: left stall + rear bumpers; high: right + front
  std::int16_t control = 0;
  std::uint16_t flags = 0;
  std::uint8_t compass = 0;      // 2 deg per unit
  std::vector<SonarReading> sonars;
  // Fields after the sonars: each present only if the firmware sent it.
  std::optional<std::uint8_t> grip_state, anport, analog, digin, digout;
  std::optional<std::uint16_t> battery_x10;  // 0.1 V
  std::optional<std::uint8_t> charge_state;
  std::optional<std::int16_t> rot_vel;       // 0.1 deg/s
  std::optional<std::uint16_t> fault_flags;
  std::optional<std::int16_t> lat_vel;
  std::optional<std::int8_t> temperature;
  std::optional<std::uint8_t> state_of_charge;
  std::optional<std::uint32_t> uc_time;
  std::optional<std::uint32_t> flags3;

  bool motorsEnabled() const { return (flags & kFlagMotorsEnabled) != 0; }
  bool leftStall() const { return (stall_bumpers & 0x0001) != 0; }
  bool rightStall() const { return (stall_bumpers & 0x0100) != 0; }
};

// Number of optional tail fields (grip_state ... flags3) in the order they are sent.
constexpr int kSipTailFieldCount = 14;

// Decodes a SIP. On failure returns nullopt and, if `error` is given, says why (wrong type,
// packet too short for the fixed part or the announced sonar readings).
std::optional<Sip> decodeSip(const Packet& packet, std::string* error = nullptr);
// Encodes a SIP with the first `tail_fields` optional fields (0..kSipTailFieldCount); a
// field without a value is sent as 0.
std::vector<std::uint8_t> encodeSip(const Sip& sip, int tail_fields);

// SYNC2 reply: name, class, subclass (NUL-terminated strings).
struct RobotIdentity {
  std::string name;
  std::string robot_class;
  std::string subclass;  // lower-cased on decode, as ARIA does
};
std::optional<RobotIdentity> decodeSync2(const Packet& packet, std::string* error = nullptr);
std::vector<std::uint8_t> encodeSync2(const RobotIdentity& identity);

// CONFIGpac in ARIA's parse order. Fields up to TransKI are required; the later ones are
// read only when present (older firmware sends fewer), as ARIA does.
struct ConfigPac {
  std::string robot_type, subtype, serial;
  std::uint8_t four_motors = 0;
  std::uint16_t rot_vel_top = 0, trans_vel_top = 0, rot_acc_top = 0, trans_acc_top = 0, pwm_max = 0;
  std::string name;
  std::uint8_t sip_cycle_ms = 0, host_baud = 0, aux1_baud = 0;
  std::uint16_t has_gripper = 0, front_sonar = 0;
  std::uint8_t rear_sonar = 0;
  std::uint16_t low_battery = 0, rev_count = 0, watchdog = 0;
  std::uint8_t normal_mpacs = 0;
  std::uint16_t stall_val = 0, stall_count = 0, joy_vel = 0, joy_rot_vel = 0;
  std::uint16_t rot_vel_max = 0, trans_vel_max = 0;  // deg/s, mm/s
  std::uint16_t rot_acc = 0, rot_decel = 0;          // deg/s^2
  std::uint16_t rot_kp = 0, rot_kv = 0, rot_ki = 0;
  std::uint16_t trans_acc = 0, trans_decel = 0;      // mm/s^2
  std::uint16_t trans_kp = 0, trans_kv = 0, trans_ki = 0;
  // Optional tail.
  std::optional<std::uint8_t> front_bumps, rear_bumps, charger, sonar_cycle, auto_baud, gyro_type;
  std::optional<std::int16_t> drift_factor;
  std::optional<std::uint8_t> aux2_baud, aux3_baud;
  std::optional<std::uint16_t> ticks_mm, shutdown_volts;
  std::optional<std::string> firmware_version;
};
std::optional<ConfigPac> decodeConfigPac(const Packet& packet, std::string* error = nullptr);
// Encodes every field (optional ones without a value as 0 / "").
std::vector<std::uint8_t> encodeConfigPac(const ConfigPac& config);

}  // namespace aria
}  // namespace amigobot_tracking
