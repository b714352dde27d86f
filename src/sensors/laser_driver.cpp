#include "amigobot_tracking/sensors/laser_driver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "amigobot_tracking/core/support/error_text.h"
#include "amigobot_tracking/link/address.h"
#include "amigobot_tracking/sensors/laser_registry.h"

namespace amigobot_tracking {
namespace sensors {

double systemSeconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

void LaserDriverConfig::validate() const {
  const std::string bad = core::checkFields(laserDriverFields(), *this);  // the model known, the periods bounded
  if (!bad.empty()) throw std::invalid_argument(bad);
  const LaserModelEntry& entry = laserModelEntry(model);
  if (port.empty()) throw std::invalid_argument("port: empty (expected /dev/ttyACM0 or host:port)");
  bool is_tcp = false;
  std::string opened;  // "laser_emulator:PORT" judged as the pty or host:port it stands for (always its link)
  try {
    opened = resolveLaserPort(model, port);
    is_tcp = link::parseTcpAddress(opened).has_value();  // the one address rule
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("port: ") + e.what());
  }
  if (!is_tcp && !entry.serial()) {
    throw std::invalid_argument("port: " + model + " is reached over TCP only: expected host:port, got '" + port + "'");
  }
  if (is_tcp && !entry.tcp()) {
    throw std::invalid_argument("port: " + model + " is a serial device: expected e.g. /dev/ttyUSB0, got '" + port + "'");
  }
  if (baud != 0 && entry.bauds.empty()) {
    throw std::invalid_argument("baud: " + model + " has no speed to choose (leave it 0), got " + std::to_string(baud));
  }
  if (baud != 0 && std::find(entry.bauds.begin(), entry.bauds.end(), baud) == entry.bauds.end()) {
    std::string allowed;
    for (int b : entry.bauds) allowed += (allowed.empty() ? "" : " or ") + std::to_string(b);
    throw std::invalid_argument("baud: " + model + " runs at " + allowed + ", got " + std::to_string(baud));
  }
}

LaserDriver::LaserDriver(LaserDriverConfig config) : config_(std::move(config)) {
  config_.validate();
  config_.port = resolveLaserPort(config_.model, config_.port);  // what to open, and to name in errors
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
      const LaserModelEntry& entry = laserModelEntry(config_.model);
      device_ = entry.open(config_.port, config_.baud == 0 && !entry.bauds.empty() ? entry.bauds.front() : config_.baud);
    } catch (const std::exception& e) {
      fail(core::libraryMessage(e.what()));
      return false;
    }
    ++counters_.opens;
    motor_on_ = true;
    identity_ = device_->identity();
    last_scan_ = systemSeconds();
    last_error_.clear();
  }
  try {
    const bool wanted = motor_wanted_;
    if (wanted != motor_on_) {
      device_->setMotor(wanted);
      motor_on_ = wanted;
      last_scan_ = systemSeconds();  // the stall clock starts when the motor does
    }
    if (!motor_on_) {
      std::this_thread::sleep_for(std::chrono::duration<double>(timeout));
      return false;
    }
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
    fail(core::libraryMessage(e.what()));
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
