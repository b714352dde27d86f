#include "amigobot_tracking/sensors/laser_driver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "amigobot_tracking/link/address.h"

namespace amigobot_tracking {
namespace sensors {

double systemSeconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

void LaserDriverConfig::validate() const {
  if (model != "hokuyo_urg" && model != "sick_tim5xx" && model != "sick_lms1xx" && model != "rplidar") {
    throw std::invalid_argument("model: '" + model + "' has no driver here (hokuyo_urg | sick_tim5xx | sick_lms1xx | rplidar)");
  }
  if (port.empty()) throw std::invalid_argument("port: empty (expected /dev/ttyACM0 or host:port)");
  bool is_tcp = false;
  try {
    is_tcp = link::parseTcpAddress(port).has_value();  // the one address rule
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("port: ") + e.what());
  }
  if (!is_tcp && (model == "sick_tim5xx" || model == "sick_lms1xx")) {
    throw std::invalid_argument("port: " + model + " speaks CoLa-A over TCP: expected host:port, got '" + port + "'");
  }
  if (is_tcp && model == "rplidar") {
    throw std::invalid_argument("port: rplidar (A1/A2) is a serial device: expected e.g. /dev/ttyUSB0, got '" + port + "'");
  }
  if (baud != 0 && model != "rplidar") {
    throw std::invalid_argument("baud: only the rplidar's is chosen here (" + model + ": leave it 0), got " + std::to_string(baud));
  }
  if (baud != 0 && baud != 115200 && baud != 256000) {
    throw std::invalid_argument("baud: rplidar runs at 115200 (A1, A2M8) or 256000 (A2M12, A3), got " + std::to_string(baud));
  }
  if (!(reconnect_period > 0.0 && reconnect_period <= 60.0)) throw std::invalid_argument("reconnect_period: must be within (0, 60] s");
  if (!(stall_timeout > 0.0 && stall_timeout <= 60.0)) throw std::invalid_argument("stall_timeout: must be within (0, 60] s");
}

LaserDriver::LaserDriver(LaserDriverConfig config) : config_(std::move(config)) {
  config_.validate();
  backoff_ = config_.reconnect_period;
}

void LaserDriver::close() { device_.reset(); }

void LaserDriver::fail(const std::string& why) {
  last_error_ = why;
  device_.reset();
  next_open_ = systemSeconds() + backoff_;
  backoff_ = std::min(2.0 * backoff_, 8.0 * config_.reconnect_period);
}

bool LaserDriver::poll(LaserScanData* scan, double timeout) {
  const double now = systemSeconds();
  if (!device_) {
    if (now < next_open_) {
      std::this_thread::sleep_for(std::chrono::duration<double>(std::min(timeout, next_open_ - now)));
      return false;
    }
    try {
      if (config_.model == "hokuyo_urg") {
        device_ = openHokuyo(config_.port);
      } else if (config_.model == "rplidar") {
        device_ = openRplidar(config_.port, config_.baud == 0 ? 115200 : config_.baud);
      } else {
        device_ = openCola(config_.model, config_.port);
      }
    } catch (const std::exception& e) {
      fail(e.what());
      return false;
    }
    ++counters_.opens;
    identity_ = device_->identity();
    last_scan_ = systemSeconds();
    last_error_.clear();
  }
  try {
    if (!device_->read(scan, static_cast<int>(std::ceil(timeout * 1000.0)))) {
      if (systemSeconds() - last_scan_ > config_.stall_timeout) {
        ++counters_.stalls;
        fail(config_.model + " " + config_.port + ": no scan for " + std::to_string(config_.stall_timeout) + " s");
      }
      return false;
    }
  } catch (const ScanError& e) {
    ++counters_.damaged;
    last_error_ = e.what();
    if (systemSeconds() - last_scan_ > config_.stall_timeout) {
      ++counters_.stalls;
      fail(e.what());
    }
    return false;
  } catch (const std::exception& e) {
    ++counters_.link_failures;
    fail(e.what());
    return false;
  }
  last_scan_ = systemSeconds();
  backoff_ = config_.reconnect_period;  // a good scan: the next failure waits the shortest time
  scan->sequence = sequence_++;
  ++counters_.scans;
  return true;
}

}  // namespace sensors
}  // namespace amigobot_tracking
