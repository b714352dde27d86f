// The CoLa-A side of the emulated SICK lasers. The TiM5xx answers what it is asked and
// streams once LMDscandata is enabled. The LMS1xx, as its telegram listing describes, also
// reports its scan configuration (LMPscancfg) and status (STlms), and measures only after
// an authorised client (SetAccessMode 03 with the client password) started it (LMCstartmeas).
#include <cmath>
#include <algorithm>
#include <memory>
#include <sstream>
#include <vector>

#include "amigobot_tracking/sensors/cola_a.h"
#include "amigobot_tracking/sensors/cola_protocol.h"
#include "amigobot_tracking/sensors/laser_session.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

constexpr const char* kClientPassword = "F4724744";  // SICK's default for "authorised client"

class ColaSession : public LaserSession {
 public:
  ColaSession(LaserModel model, std::string serial)
      : model_(std::move(model)), cola_(model_.protocolGeometry<ColaGeometry>()), serial_(std::move(serial)),
        lms_(cola_.measures_on_command),
        measuring_(!lms_) {}

  std::string receive(const std::string& bytes, const EmulatedScan& latest) override {
    buffer_ += bytes;
    std::string out, body;
    while (cola::nextTelegram(&buffer_, &body)) {
      requests_.push_back(body);
      out += cola::frame(answer(body, latest));
    }
    return out;
  }

  std::string stream(const EmulatedScan& scan) override {
    return streaming_ && measuring_ ? cola::frame(telegram("sSN", scan)) : "";
  }

 private:
  std::string answer(const std::string& body, const EmulatedScan& latest) {
    if (body == "sRN LMDscandata") return measuring_ ? telegram("sRA", latest) : "sFA 4";  // local condition failed
    if (body == "sEN LMDscandata 1" || body == "sEN LMDscandata 0") {
      streaming_ = body.back() == '1';
      return "sEA LMDscandata " + std::string(1, body.back());
    }
    if (body.rfind("sRI", 0) == 0 || body == "sRN DeviceIdent") {
      return lms_ ? "sRA DeviceIdent B LMS111-emul 5 V1.80" : "sRA 0 B TiM5xx-emul 4 V1.0";
    }
    if (body == "sRN SerialNumber") return "sRA SerialNumber " + cola::hex(static_cast<std::uint32_t>(serial_.size())) + " " + serial_;
    if (body == "sRN FirmwareVersion") return "sRA FirmwareVersion 4 V1.0";
    if (body == "sRN SCdevicestate") return "sRA SCdevicestate 1";
    if (body.rfind("sMN SetAccessMode", 0) == 0) {
      authorised_ = body == std::string("sMN SetAccessMode 03 ") + kClientPassword;
      return lms_ && !authorised_ ? "sAN SetAccessMode 0" : "sAN SetAccessMode 1";
    }
    if (body == "sMN LMCstartmeas" || body == "sMN LMCstopmeas") {
      if (lms_ && !authorised_) return "sFA 1";  // access denied
      measuring_ = body == "sMN LMCstartmeas";
      return "sAN " + body.substr(4) + " 0";
    }
    if (body == "sMN Run") {
      authorised_ = false;  // Run ends the configuration session
      return "sAN Run 1";
    }
    if (body == "sMN mSCreboot") return "sAN mSCreboot";
    if (lms_ && body == "sRN LMPscancfg") return "sRA LMPscancfg " + lmpScanCfg();
    if (body == "sRN LMPoutputRange") {  // sectors, resolution, start, stop (clearpath LMS1xx, sick_scan)
      return "sRA LMPoutputRange 1 " + cola::hex(static_cast<std::uint32_t>(cola_.angular_step)) + " " +
             cola::hexSigned(cola_.start_angle) + " " + cola::hexSigned(stopAngle());
    }
    if (body.rfind("sWN LMPoutputRange ", 0) == 0) return "sWA LMPoutputRange";  // the range stays the full one
    if (body.rfind("sWN LMDscandatacfg ", 0) == 0) return scanDataConfig(body);
    if (lms_ && body.rfind("sMN mLMPsetscancfg ", 0) == 0) {
      // Accepted without change: the emulated configuration is set on the command line.
      return authorised_ ? "sAN mLMPsetscancfg 0 " + lmpScanCfg() : "sFA 1";
    }
    if (lms_ && body == "sMN mEEwriteall") return "sAN mEEwriteall 1";
    if (lms_ && body == "sRN STlms") {
      // 3 idle; 7 (ready for measurement) once started: the emulated device is long warmed
      // up, so clearpath's LMS1xx_node, which asks once right after LMCstartmeas, proceeds.
      return "sRA STlms " + std::string(measuring_ ? "7" : "3") + " 0 8 00:00:00 A 01.01.2000 0 0 0";
    }
    return "sFA 2";  // SICK error 2: unknown command
  }

  // Frequency, sector count, resolution, start, stop, as LMPscancfg lists them.
  std::string lmpScanCfg() const {
    return cola::hex(static_cast<std::uint32_t>(cola_.scan_frequency)) + " 1 " +
           cola::hex(static_cast<std::uint32_t>(cola_.angular_step)) + " " + cola::hexSigned(cola_.start_angle) + " " +
           cola::hexSigned(stopAngle());
  }

  // The nominal stop angle, as devices report it: a real TiM5xx answers 225 deg (225510),
  // not start + 810 x 0.3333 deg (sick_scan's doc/tim5xx_startup_sequence.txt).
  int stopAngle() const {
    const long span = static_cast<long>(cola_.angular_step) * (cola_.beam_count - 1);
    return cola_.start_angle + static_cast<int>((span + 500) / 1000 * 1000);  // to 0.1 deg
  }

  // sWN LMDscandatacfg channel 00 remission resolution unit encoder 00 position name comment
  // time interval: the remission flag adds an RSSI1 channel, 16-bit at resolution 1 (else 8-bit).
  std::string scanDataConfig(const std::string& body) {
    std::istringstream in(body);
    std::vector<std::string> f;
    for (std::string field; in >> field;) f.push_back(field);
    if (f.size() < 6) return "sFA 3";  // SICK error 3: wrong parameter count
    remission_ = f[4] == "1";
    remission_8bit_ = f[5] == "0";
    return "sWA LMDscandatacfg";
  }

  std::string telegram(const char* command, const EmulatedScan& scan) {
    cola::ScanTelegram t;
    t.command = command;
    t.serial = 0x1234567;
    t.telegram_counter = ++telegrams_;
    t.scan_counter = static_cast<std::uint32_t>(scan.index);
    t.time_since_start_us = static_cast<std::uint32_t>(std::llround(scan.t * 1e6));
    t.time_of_transmission_us = static_cast<std::uint32_t>(std::llround((scan.t + model_.scanTime()) * 1e6));
    t.scan_frequency = static_cast<std::uint32_t>(cola_.scan_frequency);
    t.measurement_frequency = static_cast<std::uint32_t>(std::lround(1.0 / model_.timeIncrement() / 100.0));
    t.start_angle = cola_.start_angle;
    t.angular_step = static_cast<std::uint32_t>(cola_.angular_step);
    t.ranges = deviceRanges(model_, scan.ranges);
    if (remission_) {
      t.rssi_8bit = remission_8bit_;
      for (std::uint32_t range : t.ranges) t.rssi.push_back(remission(range));
    }
    return cola::encodeScan(t);
  }

  LaserModel model_;
  ColaGeometry cola_;  // model_'s numbers, as CoLa-A's (throws at construction for another's)
  std::string serial_, buffer_;
  // An emulated remission: none without echo, weaker with distance (a grey wall).
  std::uint32_t remission(std::uint32_t range_mm) const {
    if (range_mm == 0) return 0;
    const double full = remission_8bit_ ? 255.0 : 1000.0;
    return static_cast<std::uint32_t>(std::lround(full * std::max(0.1, 1.0 - range_mm / (1000.0 * model_.range_max))));
  }

  bool lms_, measuring_, streaming_ = false, authorised_ = false, remission_ = false, remission_8bit_ = false;
  std::uint32_t telegrams_ = 0;
};

}  // namespace

std::unique_ptr<LaserSession> makeColaSession(const LaserModel& model, const std::string& serial) {
  return std::make_unique<ColaSession>(model, serial);
}

}  // namespace sensors
}  // namespace amigobot_tracking
