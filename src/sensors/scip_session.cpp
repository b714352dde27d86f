// The emulator's SCIP 2.0 session (a URG-04LX in SCIP 2.0 mode): the replies urg_c and MRPT's
// CHokuyoURG expect, and the scans they ask for.
#include <algorithm>
#include <cmath>

#include "amigobot_tracking/sensors/laser_session.h"
#include "amigobot_tracking/sensors/scip.h"
#include "amigobot_tracking/sensors/scip_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

// SCIP 2.0 (URG-04LX in SCIP 2.0 mode).
class ScipSession : public LaserSession {
 public:
  ScipSession(LaserModel model, std::string serial)
      : model_(std::move(model)), scip_(model_.protocolGeometry<ScipGeometry>()), serial_(std::move(serial)) {}

  std::string receive(const std::string& bytes, const EmulatedScan& latest) override {
    std::string out;
    for (char c : bytes) {
      if (c != '\n' && c != '\r') {
        line_ += c;
        continue;
      }
      if (!line_.empty()) out += answer(line_, latest);
      line_.clear();
    }
    return out;
  }

  std::string stream(const EmulatedScan& scan) override {
    if (!streaming_) return "";
    if (skip_++ % (active_.interval + 1) != 0) return "";
    std::string echo = active_line_;
    if (active_.count > 0) {
      --remaining_;
      echo.replace(13, 2, (remaining_ < 10 ? "0" : "") + std::to_string(remaining_));
      if (remaining_ == 0) streaming_ = false;
    }
    return data(echo, active_, scan);
  }

 private:
  std::string answer(const std::string& line, const EmulatedScan& latest) {
    requests_.push_back(line);
    const std::string command = line.substr(0, 2);
    if (line == "SCIP2.0") return scip::reply(line, "00");
    // The info replies carry every line urg_c (urg_node's library, current/src/urg_sensor.c)
    // counts and cuts: VV 5 entries (VV_RESPONSE_LINES 7 with echo and status), FIRM
    // "version(date)" (urg_sensor_firmware_version cuts at '('); II 7 entries
    // (II_RESPONSE_LINES 9) with STAT, and MESM with a space (urg_sensor_state cuts at ' ').
    if (command == "VV") {
      return scip::infoReply(line, {"VEND:Hokuyo Automatic Co.,Ltd.", "PROD:SOKUIKI Sensor " + scip_.product + " (emulated)",
                                    "FIRM:3.4.03(17/Dec./2012)", "PROT:SCIP 2.0", "SERI:" + serial_});
    }
    if (command == "PP") {
      return scip::infoReply(line, {"MODL:" + scip_.product + "(Hokuyo Automatic Co.,Ltd.)", "DMIN:" + std::to_string(scip_.dmin_mm),
                                    "DMAX:" + std::to_string(scip_.dmax_mm), "ARES:" + std::to_string(scip_.ares),
                                    "AMIN:" + std::to_string(scip_.amin), "AMAX:" + std::to_string(scip_.amax),
                                    "AFRT:" + std::to_string(scip_.afrt), "SCAN:" + std::to_string(scip_.scan_rpm)});
    }
    if (command == "II") {
      return scip::infoReply(line, {"MODL:" + scip_.product + "(Hokuyo Automatic Co.,Ltd.)", "LASR:" + std::string(laser_on_ ? "ON" : "OFF"),
                                    "SCSP:Initial(" + std::to_string(scip_.scan_rpm) + "[rpm])",
                                    std::string("MESM:") + (laser_on_ ? "Measuring by Normal Mode" : "Idling (laser off)"),
                                    "SBPS:Ethernet (emulated)",
                                    "TIME:" + scip::encode(static_cast<std::uint32_t>(latest.t * 1000.0) & 0xFFFFFFu, 4),
                                    "STAT:Sensor works well."});
    }
    if (command == "BM") {
      laser_on_ = true;
      return scip::reply(line, "00");
    }
    if (command == "QT" || command == "RS") {
      laser_on_ = streaming_ = false;
      return scip::reply(line, "00");
    }
    if (command == "HS" || command == "SS" || command == "CR" || command == "TM") return scip::reply(line, "00");
    scip::ScanRequest request;
    if (command == "MD" || command == "MS" || command == "GD" || command == "GS") {
      if (!scip::parseScanRequest(line, &request).empty()) return scip::reply(line, "02");
      if (request.end >= scip_.ares) return scip::reply(line, "04");
      if (!request.continuous()) return laser_on_ ? data(line, request, latest) : scip::reply(line, "02");
      laser_on_ = streaming_ = true;
      active_ = request;
      active_line_ = line;
      remaining_ = request.count;
      skip_ = 0;
      return scip::reply(line, "00");
    }
    return scip::reply(line, "0E");  // unknown command
  }

  // One data reply for steps request.start..end grouped by `cluster` (the nearest range).
  std::string data(const std::string& echo, const scip::ScanRequest& request, const EmulatedScan& scan) const {
    const std::vector<std::uint32_t> coded = deviceRanges(model_, scan.ranges);
    std::vector<std::uint32_t> ranges;
    for (int step = request.start; step <= request.end; step += request.cluster) {
      std::uint32_t nearest = 0;
      bool any = false;
      for (int s = step; s < std::min(step + request.cluster, request.end + 1); ++s) {
        const int beam = s - scip_.amin;
        const std::uint32_t value = beam >= 0 && beam < static_cast<int>(coded.size()) ? coded[static_cast<std::size_t>(beam)] : 1u;
        if (!any || (value >= 20 && (nearest < 20 || value < nearest))) nearest = value;
        any = true;
      }
      ranges.push_back(nearest);
    }
    const auto stamp = static_cast<std::uint32_t>(std::llround(scan.t * 1000.0));
    return scip::scanReply(echo, request.continuous() ? "99" : "00", stamp, ranges, request.encodingChars());
  }

  LaserModel model_;
  ScipGeometry scip_;  // model_'s numbers, as SCIP's (throws at construction for another's)
  std::string serial_, line_, active_line_;
  scip::ScanRequest active_;
  bool laser_on_ = false, streaming_ = false;
  int remaining_ = 0;
  std::uint64_t skip_ = 0;
};

}  // namespace

std::unique_ptr<LaserSession> makeScipSession(const LaserModel& model, const std::string& serial) {
  return std::make_unique<ScipSession>(model, serial);
}

}  // namespace sensors
}  // namespace amigobot_tracking
