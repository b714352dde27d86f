#include "amigobot_tracking/sensors/laser_registry.h"

#include <stdexcept>

#include "amigobot_tracking/link/address.h"
#include "amigobot_tracking/sensors/cola_protocol.h"
#include "amigobot_tracking/sensors/laser_protocol.h"
#include "amigobot_tracking/sensors/rplidar_protocol.h"
#include "amigobot_tracking/sensors/scip_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

LaserModel hokuyoUrg() {
  LaserModel m;
  m.name = "hokuyo_urg";
  m.protocol = &scipProtocol();
  const ScipGeometry pp;  // the URG-04LX's PP numbers are ScipGeometry's defaults
  m.setProtocolGeometry(pp);
  m.range_min = pp.dmin_mm / 1000.0;
  m.range_max = pp.dmax_mm / 1000.0;
  m.rate = pp.scan_rpm / 60.0;
  return m;
}

LaserModel sickTim5xx() {
  LaserModel m;
  m.name = "sick_tim5xx";
  m.protocol = &colaProtocol();
  const ColaGeometry telegram;  // the TiM5xx's telegram numbers are ColaGeometry's defaults
  m.setProtocolGeometry(telegram);
  m.range_min = 0.05;
  m.range_max = 10.0;
  m.rate = telegram.scan_frequency / 100.0;
  return m;
}

LaserModel sickLms1xx() {
  LaserModel m;
  m.name = "sick_lms1xx";
  m.protocol = &colaProtocol();
  // The LMS111 data sheet's operating range starts at 0.5 m, but the device reports echoes
  // from 0.01 m on (real captures carry 0.126 m) and clearpath's LMS1xx driver publishes
  // range_min 0.01: dropping them would lose what the device measured.
  m.range_min = 0.01;
  m.range_max = 20.0;
  ColaGeometry lms;
  lms.measures_on_command = true;
  m.setProtocolGeometry(lms);
  setLms1xxScanConfig(&m, 25.0, 0.5);  // the factory scan, as the entry's scan_setting says
  return m;
}

LaserModel rplidarA1() {
  LaserModel m;
  m.name = "rplidar";
  m.protocol = &rplidarProtocol();
  m.setProtocolGeometry(RplidarGeometry());  // the A1M8's standard SCAN mode
  m.range_min = 0.15;  // A1M8 data sheet: 0.15 .. 12 m
  m.range_max = 12.0;
  m.rate = 5.5;
  return m;
}

// Built on first use (not at static initialisation), so any other static may read it. One
// entry per model: name, what it is, link, serial speeds, model (with its protocol: the
// driver's device and the emulator's session), the scan to choose (std::nullopt: fixed).
const std::vector<LaserModelEntry>& registry() {
  static const std::vector<LaserModelEntry> models{
      {"hokuyo_urg", "Hokuyo URG-04LX, SCIP 2.0: 240 deg, 0.352 deg, 10 Hz, 0.02 .. 4 m", LaserLink::kSerialOrTcp, {},
       hokuyoUrg, std::nullopt},
      {"sick_tim5xx", "SICK TiM5xx, CoLa-A over TCP: 270 deg, 0.333 deg, 15 Hz, 0.05 .. 10 m", LaserLink::kTcp, {},
       sickTim5xx, std::nullopt},
      {"sick_lms1xx", "SICK LMS111, CoLa-A over TCP: 270 deg, 0.5 deg, 25 Hz, 0.01 .. 20 m", LaserLink::kTcp, {},
       sickLms1xx, LaserScanSetting{"25 Hz at 0.5 | 0.25 deg, 50 Hz at 0.5 deg", 25.0, 0.5, setLms1xxScanConfig}},
      {"rplidar", "Slamtec RPLIDAR A1M8 (A2, A3), serial: 360 deg, ~1 deg, 5.5 Hz, 0.15 .. 12 m", LaserLink::kSerial,
       {115200, 256000}, rplidarA1, std::nullopt},
  };
  return models;
}

}  // namespace

const std::vector<LaserModelEntry>& laserModels() { return registry(); }

std::vector<std::string> laserModelNames() {
  std::vector<std::string> names;
  for (const LaserModelEntry& e : registry()) names.push_back(e.name);
  return names;
}

std::string laserModelList() {
  std::string list;
  for (const LaserModelEntry& e : registry()) list += (list.empty() ? "" : " | ") + e.name;
  return list;
}

const LaserModelEntry& laserModelEntry(const std::string& name) {
  for (const LaserModelEntry& e : registry()) {
    if (e.name == name) return e;
  }
  throw std::invalid_argument("model: '" + name + "' is not a known laser (" + laserModelList() + ")");
}

LaserModel laserModel(const std::string& name) { return laserModelEntry(name).model(); }

std::unique_ptr<LaserDevice> LaserModelEntry::open(const std::string& port, int baud) const {
  return protocolOf(model()).open(name, port, baud);
}

std::string LaserEndpoint::address() const { return pty.empty() ? "localhost:" + std::to_string(tcp_port) : pty; }

LaserEndpoint laserEmulatorEndpoint(const std::string& model, int port) {
  const LaserModelEntry& entry = laserModelEntry(model);
  if (port < 1 || port > 65535) {
    throw std::invalid_argument("endpoint: port " + std::to_string(port) + " outside 1 .. 65535 (the driver must know it)");
  }
  LaserEndpoint endpoint;
  if (entry.tcp()) {
    endpoint.tcp_port = port;
  } else {
    endpoint.pty = "/tmp/amigobot_laser_" + entry.name + "_" + std::to_string(port);
  }
  return endpoint;
}

std::string resolveLaserPort(const std::string& model, const std::string& port) {
  // The address rule reads "laser_emulator:PORT" as a host and a checked port: one port rule.
  const std::optional<link::TcpAddress> address = port.empty() ? std::nullopt : link::parseTcpAddress(port);
  if (!address || address->host != "laser_emulator") return port;
  return laserEmulatorEndpoint(model, address->port).address();
}

const core::FieldTable<LaserDriverConfig>& laserDriverFields() {
  using D = LaserDriverConfig;
  using core::field;
  static const core::FieldTable<D> table = {
      field("model", &D::model, "-",
            "the laser: hokuyo_urg (Hokuyo URG-04LX, SCIP 2.0 via MRPT's CHokuyoURG), sick_tim5xx (SICK TiM5xx, "
            "CoLa-A over TCP), sick_lms1xx (SICK LMS111, CoLa-A over TCP) or rplidar (Slamtec RPLIDAR A1M8, A2, A3: "
            "Slamtec's binary protocol over serial)",
            core::oneOf(laserModelNames())),
      field("port", &D::port, "-",
            "serial device (hokuyo_urg, rplidar) or host:port (hokuyo_urg; sick_tim5xx, sick_lms1xx: HOST:2111 for "
            "CoLa-A, or HOST:2112 while that port speaks CoLa-A); laser_emulator:PORT -> where laser_emulator "
            "--endpoint PORT serves the model: localhost:PORT for a TCP model, the pty "
            "/tmp/amigobot_laser_MODEL_PORT for a serial-only one"),
      field("reconnect_period", &D::reconnect_period, "s",
            "first wait before reopening a lost or failed laser; doubles on each failure up to 8x, back to this after "
            "a good scan",
            core::boundedTimeout()),
      field("stall_timeout", &D::stall_timeout, "s",
            "no good scan for this long -> the link is closed and reopened (an rplidar motor stopped by the stop_motor "
            "service is no stall)",
            core::boundedTimeout()),
      field("baud", &D::baud, "baud",
            "rplidar only: 115200 (A1, A2M8) or 256000 (A2M12, A3; set through termios2); 0 = 115200. Another model "
            "refuses any value but 0",
            core::nonNegative()),
  };
  return table;
}

}  // namespace sensors
}  // namespace amigobot_tracking
