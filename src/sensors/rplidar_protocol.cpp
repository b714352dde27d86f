// Slamtec's RPLIDAR protocol (A1, A2, A3): a revolution of samples at the device's own angles,
// published on a fixed grid of `bins`; the driver's client (rplidar_device.cpp), the
// emulator's session (rplidar_session.cpp); a motor the host starts and stops.
#include <cmath>

#include "amigobot_tracking/sensors/rplidar_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

class RplidarProtocol : public LaserProtocol {
 public:
  std::string name() const override { return "RPLIDAR"; }
  std::unique_ptr<LaserDevice> open(const std::string& /*model*/, const std::string& port, int baud) const override {
    return openRplidar(port, baud);
  }

  std::unique_ptr<LaserSession> session(const LaserModel& model, const std::string& serial) const override {
    return makeRplidarSession(model, serial);
  }
  std::uint32_t noMeasurementCode(float /*r*/) const override { return 0; }  // a node of distance 0
  bool samplesAsItTurns() const override { return true; }
  std::string malformed(std::string telegram) const override {  // node 10's check bit
    if (telegram.size() > 52) telegram[51] = static_cast<char>(telegram[51] & ~0x01);
    return telegram;
  }
  bool hasChecksum() const override { return false; }

  bool hasMotor() const override { return true; }
  std::string rosDriverAngleConvention() const override { return "rplidar_ros"; }
};

}  // namespace

double RplidarGeometry::angleMin() const { return -M_PI; }
double RplidarGeometry::angleIncrement() const { return 2.0 * M_PI / bins; }

const LaserProtocol& rplidarProtocol() {
  static const RplidarProtocol protocol;
  return protocol;
}

}  // namespace sensors
}  // namespace amigobot_tracking
