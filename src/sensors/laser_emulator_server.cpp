#include "amigobot_tracking/sensors/laser_emulator_server.h"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <limits>
#include <stdexcept>
#include <vector>

#include "amigobot_tracking/link/emulator_link.h"
#include "amigobot_tracking/sensors/laser_protocol.h"
#include "amigobot_tracking/sensors/laser_registry.h"

namespace amigobot_tracking {
namespace sensors {
std::string scanSettingChoices() {
  std::string choices;
  for (const LaserModelEntry& e : laserModels()) {
    if (e.scan_setting) choices += (choices.empty() ? "" : "; ") + e.name + ": " + e.scan_setting->choices;
  }
  return choices;
}

LaserModel emulatedLaserModel(const std::string& name, std::optional<double> frequency_hz,
                              std::optional<double> resolution_deg) {
  const LaserModelEntry& entry = laserModelEntry(name);
  LaserModel model = entry.model();
  if (!entry.scan_setting) {
    if (!frequency_hz && !resolution_deg) return model;
    std::string takers;  // from the registry, so a new model with a setting is named here too
    for (const LaserModelEntry& e : laserModels()) {
      if (e.scan_setting) takers += (takers.empty() ? "" : ", ") + e.name;
    }
    throw std::invalid_argument(std::string(frequency_hz ? "--scan-frequency" : "--resolution") + ": " + name +
                                " has a fixed scan (a scan to choose: " + (takers.empty() ? "no model" : takers) + ")");
  }
  const LaserScanSetting& setting = *entry.scan_setting;
  setting.apply(&model, frequency_hz.value_or(setting.frequency_hz), resolution_deg.value_or(setting.resolution_deg));
  return model;
}

Fault parseFault(const std::string& name) {
  if (name == "none") return Fault::kNone;
  if (name == "malformed") return Fault::kMalformed;
  if (name == "truncated") return Fault::kTruncated;
  if (name == "checksum") return Fault::kChecksum;
  if (name == "stall") return Fault::kStall;
  if (name == "disconnect") return Fault::kDisconnect;
  throw std::invalid_argument("fault: '" + name + "' (expected none | malformed | truncated | checksum | stall | disconnect)");
}

void LaserServerOptions::validate(const LaserModel& model) const {
  if (fault_every < 0) throw std::invalid_argument("fault_every: must be >= 0");
  if (fault != Fault::kNone && fault_every == 0) throw std::invalid_argument("fault_every: must be > 0 with a fault");
  if (fault == Fault::kChecksum && !protocolOf(model).hasChecksum()) {
    std::string takers;  // from the registry, as emulatedLaserModel's
    for (const LaserModelEntry& e : laserModels()) {
      if (protocolOf(e.model()).hasChecksum()) takers += (takers.empty() ? "" : ", ") + e.name;
    }
    throw std::invalid_argument("fault: checksum needs a model whose protocol has a checksum (" + takers + "); " +
                                model.name + " speaks " + protocolOf(model).name() + ", which has none");
  }
  if (!pty_link.empty() && !laserModelEntry(model.name).serial()) {
    throw std::invalid_argument("pty: " + model.name + " has no serial port (TCP only)");
  }
  if (!(stall_time > 0.0)) throw std::invalid_argument("stall_time: must be > 0");
}

LaserEmulatorServer::LaserEmulatorServer(LaserModel model, ScanSource source, PoseSource pose,
                                         LaserServerOptions options)
    : model_(std::move(model)), source_(std::move(source)), pose_(std::move(pose)), options_(std::move(options)) {
  options_.validate(model_);
  latest_.ranges.assign(static_cast<std::size_t>(model_.beams()), std::numeric_limits<float>::quiet_NaN());
}

LaserEmulatorServer::~LaserEmulatorServer() {
  if (tcp_.fd >= 0) ::close(tcp_.fd);  // the pty's master belongs to pty_terminal_
}

void LaserEmulatorServer::open() {
  try {
    if (options_.tcp_port >= 0) listener_.open(options_.bind_address, options_.tcp_port, 2);
    if (!options_.pty_link.empty()) {
      pty_terminal_.open(options_.pty_link);
      pty_.fd = pty_terminal_.master();
      pty_.session = makeSession(model_, options_.serial);
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("laser_emulator: ") + e.what());
  }
  next_scan_ = link::steadySeconds();
}

void LaserEmulatorServer::accept() {
  const int fd = listener_.accept();
  if (fd < 0) return;
  drop(tcp_);
  tcp_.fd = fd;
  tcp_.session = makeSession(model_, options_.serial);
}

void LaserEmulatorServer::drop(Link& link) {
  if (link.fd >= 0 && link.fd != pty_terminal_.master()) ::close(link.fd);
  link.fd = -1;
  link.session.reset();
  link.paced.clear();
  link.paced_sent = 0;
}

void LaserEmulatorServer::serve(Link& link) {
  char buffer[4096];
  const ssize_t n = ::read(link.fd, buffer, sizeof(buffer));
  if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR && errno != EIO)) {
    if (&link == &tcp_) drop(link);  // the pty stays, like the device's USB port
    return;
  }
  if (n < 0) return;
  const std::string out = link.session->receive(std::string(buffer, static_cast<std::size_t>(n)), latest_);
  if (!out.empty()) link::sendAvailable(link.fd, out);
}

std::string LaserEmulatorServer::damage(std::string telegram) {
  switch (options_.fault) {
    case Fault::kMalformed: return protocolOf(model_).malformed(std::move(telegram));
    case Fault::kTruncated: return telegram.substr(0, telegram.size() / 2);
    case Fault::kChecksum: return protocolOf(model_).badChecksum(std::move(telegram));
    default: return telegram;
  }
}

void LaserEmulatorServer::tick() {
  const double now = link::steadySeconds();
  // A scan leaves the device once its last beam is measured: cast at the first beam, sent
  // one sweep of the measured beams later.
  if (has_pending_ && now >= pending_due_) {
    has_pending_ = false;
    latest_ = pending_;
    send(now);
  }
  if (now < next_scan_) return;
  next_scan_ += model_.scanTime();
  if (next_scan_ < now) next_scan_ = now + model_.scanTime();  // fell behind: skip, as a device would
  core::Pose2 base;
  double t = 0.0;
  if (!pose_(&base, &t)) return;
  pending_ = source_.cast(base, t);
  if (blind_ && *blind_) pending_.ranges.assign(pending_.ranges.size(), std::numeric_limits<float>::infinity());
  // Half the rate: this scan is measured (the device's clock goes on) but never leaves.
  if (halve_ && *halve_ && cast_++ % 2 == 1) return;
  // A RPLIDAR streams each node as it is measured: its revolution leaves at once, paced.
  pending_due_ = protocolOf(model_).samplesAsItTurns() ? now : now + model_.timeIncrement() * (model_.beams() - 1);
  has_pending_ = true;
}

void LaserEmulatorServer::send(double now) {
  for (Link* link : {&tcp_, &pty_}) {
    if (!link->session || now < stall_until_) continue;
    std::string telegram = link->session->stream(latest_);
    if (telegram.empty()) continue;
    if (options_.fault_every > 0 && ++streamed_ % static_cast<std::uint64_t>(options_.fault_every) == 0) {
      if (options_.fault == Fault::kStall) {
        stall_until_ = now + options_.stall_time;
        continue;
      }
      if (options_.fault == Fault::kDisconnect && link == &tcp_) {
        drop(tcp_);
        continue;
      }
      telegram = damage(std::move(telegram));
    }
    if (protocolOf(model_).samplesAsItTurns()) {
      link->paced.erase(0, link->paced_sent);  // a late revolution: the rest of the last one goes first
      link->paced += telegram;
      link->paced_sent = 0;
      link->paced_from = now;
      link->paced_rate = static_cast<double>(link->paced.size()) / model_.scanTime();
    } else {
      link::sendAvailable(link->fd, telegram);
    }
  }
}

void LaserEmulatorServer::drain(Link& link, double now) {
  if (link.fd < 0 || link.paced_sent >= link.paced.size()) return;
  const auto due = std::min(link.paced.size(), static_cast<std::size_t>((now - link.paced_from) * link.paced_rate));
  if (due <= link.paced_sent) return;
  link::sendAvailable(link.fd, link.paced.substr(link.paced_sent, due - link.paced_sent));
  link.paced_sent = due;
}

void LaserEmulatorServer::run(const std::atomic<bool>& stop) {
  while (!stop) {
    std::vector<pollfd> fds;
    if (listener_.isOpen()) fds.push_back({listener_.fd(), POLLIN, 0});
    if (tcp_.fd >= 0) fds.push_back({tcp_.fd, POLLIN, 0});
    if (pty_.fd >= 0) fds.push_back({pty_.fd, POLLIN, 0});
    if (::poll(fds.data(), fds.size(), 5) < 0 && errno != EINTR) throw link::systemError("laser_emulator: poll");
    for (const pollfd& p : fds) {
      if (!(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
      if (p.fd == listener_.fd()) {
        accept();
      } else if (p.fd == tcp_.fd) {
        serve(tcp_);
      } else if (p.fd == pty_.fd && (p.revents & POLLIN)) {
        serve(pty_);
      }
    }
    tick();
    drain(tcp_, link::steadySeconds());
    drain(pty_, link::steadySeconds());
  }
}

}  // namespace sensors
}  // namespace amigobot_tracking
