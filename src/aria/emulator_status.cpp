#include "amigobot_tracking/aria/emulator_status.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/aria/transport.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr std::size_t kMaxLine = 65536;

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// A flag field: exactly 0 or 1.
bool readFlag(std::istringstream& in, bool* flag) {
  int value = -1;
  if (!(in >> value) || (value != 0 && value != 1)) return false;
  *flag = value == 1;
  return true;
}

}  // namespace

std::string formatStatusLine(const EmulatorStatus& s) {
  // %.17g: every double reads back exactly, 1e300 as 1e+300 (not 300 digits); 9 fields
  // of at most 24 characters each fit.
  char line[256];
  std::snprintf(line, sizeof(line), "%.17g %.17g %.17g %.17g %.17g %.17g %d %d %d", s.t, s.pose.x, s.pose.y, s.pose.theta,
                s.v, s.w, s.motors ? 1 : 0, s.open ? 1 : 0, s.watchdog ? 1 : 0);
  return line;
}

std::string parseStatusLine(const std::string& line, EmulatorStatus* status) {
  std::istringstream in(line);
  EmulatorStatus s;
  if (!(in >> s.t >> s.pose.x >> s.pose.y >> s.pose.theta >> s.v >> s.w)) {
    return "status line '" + line + "' is not 't x y theta v w motors open watchdog'";
  }
  if (!readFlag(in, &s.motors) || !readFlag(in, &s.open) || !readFlag(in, &s.watchdog)) {
    return "status line '" + line + "': motors, open and watchdog must each be 0 or 1";
  }
  std::string extra;
  if (in >> extra) return "status line '" + line + "' has extra fields";
  if (!std::isfinite(s.t) || !s.pose.isFinite() || !std::isfinite(s.v) || !std::isfinite(s.w)) {
    return "status line '" + line + "' has a non-finite number";
  }
  *status = s;
  return "";
}

StatusClient::StatusClient(std::string host, int port, double timeout, double reconnect_period)
    : host_(std::move(host)), port_(port), timeout_(timeout), reconnect_period_(reconnect_period) {}

StatusClient::~StatusClient() = default;

bool StatusClient::connected() const { return link_ != nullptr; }

std::string StatusClient::where() const { return "emulator status socket " + host_ + ":" + std::to_string(port_); }

std::string StatusClient::fail(const std::string& why) {
  link_.reset();
  buffer_.clear();
  next_attempt_ = steadySeconds() + reconnect_period_;
  last_error_ = why;
  return why;
}

std::string StatusClient::query(EmulatorStatus* status) {
  if (!link_) {
    if (steadySeconds() < next_attempt_) return last_error_;
    try {
      link_ = makeTransport(host_ + ":" + std::to_string(port_), 0);
      link_->open();
    } catch (const std::exception& e) {
      return fail("emulator status: " + std::string(e.what()));
    }
  }
  try {
    link_->write({'\n'});
    // The first complete line answers this request (one reply per request, in order).
    const double deadline = steadySeconds() + timeout_;
    std::size_t end;
    while ((end = buffer_.find('\n')) == std::string::npos) {
      const double left = deadline - steadySeconds();
      if (left <= 0.0) return fail("no reply from the " + where() + " within " + std::to_string(timeout_) + " s");
      std::uint8_t chunk[512];
      const std::size_t n = link_->read(chunk, sizeof(chunk), static_cast<int>(std::ceil(left * 1e3)));
      buffer_.append(reinterpret_cast<const char*>(chunk), n);
      if (buffer_.size() > kMaxLine) return fail(where() + " sends no line breaks");
    }
    const std::string line = buffer_.substr(0, end);
    buffer_.erase(0, end + 1);
    const std::string error = parseStatusLine(line, status);
    return error.empty() ? error : fail(where() + ": " + error);
  } catch (const std::exception& e) {
    return fail(where() + " lost: " + e.what());
  }
}

}  // namespace aria
}  // namespace amigobot_tracking
