#include "amigobot_tracking/aria/sip.h"

#include <algorithm>
#include <cctype>

#include "amigobot_tracking/aria/commands.h"

namespace amigobot_tracking {
namespace aria {
namespace {

bool fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

// Reads an optional field if the whole field remains; false once the data has run out.
template <typename T, typename Read>
bool readOptional(PayloadReader& in, std::size_t size, std::optional<T>& field, Read read) {
  if (in.remaining() < size) return false;
  field = static_cast<T>(read());
  return true;
}

}  // namespace

std::optional<Sip> decodeSip(const Packet& packet, std::string* error) {
  if (!isSipType(packet.type)) {
    fail(error, "SIP: packet type " + std::to_string(packet.type) + " is not 0x32/0x33");
    return std::nullopt;
  }
  PayloadReader in(packet.payload);
  Sip sip;
  sip.type = packet.type;
  sip.x = in.u16() & 0x7FFF;
  sip.y = in.u16() & 0x7FFF;
  sip.theta = in.s16();
  sip.left_vel = in.s16();
  sip.right_vel = in.s16();
  sip.battery = in.u8();
  sip.stall_bumpers = in.u16();
  sip.control = in.s16();
  sip.flags = in.u16();
  sip.compass = in.u8();
  const std::uint8_t sonar_count = in.u8();
  if (!in.ok()) {
    fail(error, "SIP: " + std::to_string(packet.payload.size()) + "-byte payload is shorter than the 19-byte fixed part");
    return std::nullopt;
  }
  if (in.remaining() < 3u * sonar_count) {
    fail(error, "SIP: announces " + std::to_string(sonar_count) + " sonar readings but only " +
                    std::to_string(in.remaining()) + " bytes follow");
    return std::nullopt;
  }
  sip.sonars.resize(sonar_count);
  for (auto& s : sip.sonars) {
    s.index = in.u8();
    s.range = in.u16();
  }
  auto u8 = [&] { return in.u8(); };
  auto u16 = [&] { return in.u16(); };
  auto u32 = [&] { return in.u32(); };
  readOptional(in, 1, sip.grip_state, u8) && readOptional(in, 1, sip.anport, u8) &&
      readOptional(in, 1, sip.analog, u8) && readOptional(in, 1, sip.digin, u8) &&
      readOptional(in, 1, sip.digout, u8) && readOptional(in, 2, sip.battery_x10, u16) &&
      readOptional(in, 1, sip.charge_state, u8) && readOptional(in, 2, sip.rot_vel, u16) &&
      readOptional(in, 2, sip.fault_flags, u16) && readOptional(in, 2, sip.lat_vel, u16) &&
      readOptional(in, 1, sip.temperature, u8) && readOptional(in, 1, sip.state_of_charge, u8) &&
      readOptional(in, 4, sip.uc_time, u32) && readOptional(in, 4, sip.flags3, u32);
  return sip;
}

std::vector<std::uint8_t> encodeSip(const Sip& sip, int tail_fields) {
  ArgumentWriter out;
  out.u16(sip.x & 0x7FFF).u16(sip.y & 0x7FFF).s16(sip.theta).s16(sip.left_vel).s16(sip.right_vel);
  out.u8(sip.battery).u16(sip.stall_bumpers).s16(sip.control).u16(sip.flags).u8(sip.compass);
  out.u8(static_cast<std::uint8_t>(sip.sonars.size()));
  for (const auto& s : sip.sonars) out.u8(s.index).u16(s.range);
  const int n = std::clamp(tail_fields, 0, kSipTailFieldCount);
  int i = 0;
  auto u8 = [&](const auto& f) { if (i++ < n) out.u8(static_cast<std::uint8_t>(f.value_or(0))); };
  auto u16 = [&](const auto& f) { if (i++ < n) out.u16(static_cast<std::uint16_t>(f.value_or(0))); };
  auto u32 = [&](const auto& f) { if (i++ < n) out.u32(f.value_or(0)); };
  u8(sip.grip_state); u8(sip.anport); u8(sip.analog); u8(sip.digin); u8(sip.digout);
  u16(sip.battery_x10); u8(sip.charge_state); u16(sip.rot_vel); u16(sip.fault_flags); u16(sip.lat_vel);
  u8(sip.temperature); u8(sip.state_of_charge); u32(sip.uc_time); u32(sip.flags3);
  return encodePacket(sip.type, out.bytes());
}

std::optional<RobotIdentity> decodeSync2(const Packet& packet, std::string* error) {
  if (packet.type != kSync2) {
    fail(error, "SYNC2 reply: packet type " + std::to_string(packet.type) + " is not 2");
    return std::nullopt;
  }
  PayloadReader in(packet.payload);
  RobotIdentity id;
  id.name = in.cstring();
  id.robot_class = in.cstring();
  id.subclass = in.cstring();
  if (!in.ok()) {
    fail(error, "SYNC2 reply: expected three NUL-terminated strings (name, class, subclass), got " +
                    hexDump(packet.payload));
    return std::nullopt;
  }
  std::transform(id.subclass.begin(), id.subclass.end(), id.subclass.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return id;
}

std::vector<std::uint8_t> encodeSync2(const RobotIdentity& identity) {
  return encodePacket(kSync2,
                      ArgumentWriter().cstring(identity.name).cstring(identity.robot_class).cstring(identity.subclass).bytes());
}

std::optional<ConfigPac> decodeConfigPac(const Packet& packet, std::string* error) {
  if (packet.type != kConfigPacType) {
    fail(error, "CONFIGpac: packet type " + std::to_string(packet.type) + " is not 0x20");
    return std::nullopt;
  }
  PayloadReader in(packet.payload);
  ConfigPac c;
  c.robot_type = in.cstring();
  c.subtype = in.cstring();
  c.serial = in.cstring();
  c.four_motors = in.u8();
  c.rot_vel_top = in.u16();
  c.trans_vel_top = in.u16();
  c.rot_acc_top = in.u16();
  c.trans_acc_top = in.u16();
  c.pwm_max = in.u16();
  c.name = in.cstring();
  c.sip_cycle_ms = in.u8();
  c.host_baud = in.u8();
  c.aux1_baud = in.u8();
  c.has_gripper = in.u16();
  c.front_sonar = in.u16();
  c.rear_sonar = in.u8();
  c.low_battery = in.u16();
  c.rev_count = in.u16();
  c.watchdog = in.u16();
  c.normal_mpacs = in.u8();
  for (std::uint16_t* f : {&c.stall_val, &c.stall_count, &c.joy_vel, &c.joy_rot_vel, &c.rot_vel_max,
                           &c.trans_vel_max, &c.rot_acc, &c.rot_decel, &c.rot_kp, &c.rot_kv, &c.rot_ki,
                           &c.trans_acc, &c.trans_decel, &c.trans_kp, &c.trans_kv, &c.trans_ki}) {
    *f = in.u16();
  }
  if (!in.ok()) {
    fail(error, "CONFIGpac: " + std::to_string(packet.payload.size()) +
                    "-byte payload ends before the required fields (up to TransKI)");
    return std::nullopt;
  }
  auto u8 = [&] { return in.u8(); };
  auto u16 = [&] { return in.u16(); };
  bool more = readOptional(in, 1, c.front_bumps, u8) && readOptional(in, 1, c.rear_bumps, u8) &&
              readOptional(in, 1, c.charger, u8) && readOptional(in, 1, c.sonar_cycle, u8) &&
              readOptional(in, 1, c.auto_baud, u8) && readOptional(in, 1, c.gyro_type, u8) &&
              readOptional(in, 2, c.drift_factor, u16) && readOptional(in, 1, c.aux2_baud, u8) &&
              readOptional(in, 1, c.aux3_baud, u8) && readOptional(in, 2, c.ticks_mm, u16) &&
              readOptional(in, 2, c.shutdown_volts, u16);
  if (more && in.remaining() > 0) {
    std::string version = in.cstring();
    if (in.ok()) c.firmware_version = version;
  }
  return c;
}

std::vector<std::uint8_t> encodeConfigPac(const ConfigPac& c) {
  ArgumentWriter out;
  out.cstring(c.robot_type).cstring(c.subtype).cstring(c.serial).u8(c.four_motors);
  out.u16(c.rot_vel_top).u16(c.trans_vel_top).u16(c.rot_acc_top).u16(c.trans_acc_top).u16(c.pwm_max);
  out.cstring(c.name).u8(c.sip_cycle_ms).u8(c.host_baud).u8(c.aux1_baud);
  out.u16(c.has_gripper).u16(c.front_sonar).u8(c.rear_sonar);
  out.u16(c.low_battery).u16(c.rev_count).u16(c.watchdog).u8(c.normal_mpacs);
  for (std::uint16_t f : {c.stall_val, c.stall_count, c.joy_vel, c.joy_rot_vel, c.rot_vel_max, c.trans_vel_max,
                          c.rot_acc, c.rot_decel, c.rot_kp, c.rot_kv, c.rot_ki, c.trans_acc, c.trans_decel,
                          c.trans_kp, c.trans_kv, c.trans_ki}) {
    out.u16(f);
  }
  out.u8(c.front_bumps.value_or(0)).u8(c.rear_bumps.value_or(0)).u8(c.charger.value_or(0));
  out.u8(c.sonar_cycle.value_or(0)).u8(c.auto_baud.value_or(0)).u8(c.gyro_type.value_or(0));
  out.s16(c.drift_factor.value_or(0)).u8(c.aux2_baud.value_or(0)).u8(c.aux3_baud.value_or(0));
  out.u16(c.ticks_mm.value_or(0)).u16(c.shutdown_volts.value_or(0)).cstring(c.firmware_version.value_or(""));
  return encodePacket(kConfigPacType, out.bytes());
}

}  // namespace aria
}  // namespace amigobot_tracking
