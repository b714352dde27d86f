// Slamtec's RPLIDAR protocol (A1, A2, A3): a revolution of samples at the device's own angles,
// published on a fixed grid of `bins`; the driver's client (rplidar_device.cpp), the
// emulator's session (rplidar_session.cpp); a motor the host starts and stops.
#include <cmath>

#include "amigobot_tracking/sensors/rplidar.h"
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
  // The sample clock and the motor are not locked: the step between samples varies from one
  // revolution to the next, and each revolution starts where the last one left off. *phase:
  // [deg] the device angle of the next sample; each angle is what a node carries (1/64 deg).
  std::vector<double> revolutionAngles(const LaserModel& model, double* phase, std::mt19937& random) const override {
    const RplidarGeometry& g = model.protocolGeometry<RplidarGeometry>();
    std::uniform_real_distribution<double> jitter(-g.speed_jitter, g.speed_jitter);
    const double step = 360.0 * model.rate * (1.0 + jitter(random)) / g.sample_rate;  // [deg]
    std::vector<double> angles;
    for (; *phase < 360.0; *phase += step) {
      angles.push_back(rplidar::nodeAngle(static_cast<std::uint16_t>(std::lround(*phase * 64.0) % (360 * 64))));
    }
    *phase -= 360.0;
    return angles;
  }
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
