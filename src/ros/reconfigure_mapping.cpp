#include "amigobot_tracking/ros/reconfigure_mapping.h"

#include <dynamic_reconfigure/Config.h>

namespace amigobot_tracking {
namespace ros_layer {
namespace {

using Table = core::FieldTable<core::ControllerConfig>;

const core::Field<core::ControllerConfig>* liveField(const std::string& name, core::FieldType type,
                                                     std::string* error) {
  const core::Field<core::ControllerConfig>* f = core::findField(core::controllerFields(), name);
  if (!f || !f->live || f->type != type) {
    *error = "reconfigure entry '" + name + "' is no live controller field of that type (cfg/Tracking.cfg)";
    return nullptr;
  }
  return f;
}

// Calls visit(field, entry value&) for every entry of the message, the field found by name.
template <class Visit>
std::string forEachEntry(dynamic_reconfigure::Config& msg, Visit&& visit) {
  std::string error;
  for (auto& p : msg.doubles)
    if (auto* f = liveField(p.name, core::FieldType::kReal, &error)) visit(*f, p.value);
  for (auto& p : msg.ints)
    if (auto* f = liveField(p.name, core::FieldType::kInteger, &error)) visit(*f, p.value);
  for (auto& p : msg.bools)
    if (auto* f = liveField(p.name, core::FieldType::kBoolean, &error)) visit(*f, p.value);
  for (auto& p : msg.strs)
    if (auto* f = liveField(p.name, core::FieldType::kText, &error)) visit(*f, p.value);
  return error;
}

template <class T>
core::FieldValue asField(const core::Field<core::ControllerConfig>& f, const T& v) {
  switch (f.type) {
    case core::FieldType::kReal: return static_cast<double>(v);
    case core::FieldType::kInteger: return static_cast<int>(v);
    case core::FieldType::kBoolean: return static_cast<bool>(v);
    case core::FieldType::kText: break;
  }
  return core::FieldValue();
}
core::FieldValue asField(const core::Field<core::ControllerConfig>&, const std::string& v) { return v; }

template <class T>
void assign(const core::FieldValue& v, T* out) {
  if (const double* d = std::get_if<double>(&v)) *out = static_cast<T>(*d);
  if (const int* i = std::get_if<int>(&v)) *out = static_cast<T>(*i);
  if (const bool* b = std::get_if<bool>(&v)) *out = static_cast<T>(*b);
}
void assign(const core::FieldValue& v, std::string* out) { *out = std::get<std::string>(v); }

}  // namespace

std::string applyReconfigure(const TrackingConfig& config, core::ControllerConfig* controller) {
  dynamic_reconfigure::Config msg;
  config.__toMessage__(msg);
  return forEachEntry(msg, [&](const core::Field<core::ControllerConfig>& f, const auto& value) {
    f.set(*controller, asField(f, value));
  });
}

std::string fillReconfigure(const core::ControllerConfig& controller, TrackingConfig* config) {
  dynamic_reconfigure::Config msg;
  config->__toMessage__(msg);
  const std::string error = forEachEntry(
      msg, [&](const core::Field<core::ControllerConfig>& f, auto& value) { assign(f.get(controller), &value); });
  config->__fromMessage__(msg);
  return error;
}

std::string describeLiveFields(const core::ControllerConfig& controller) {
  std::string out;
  core::visitFields(core::controllerFields(), controller, [&](const auto& f, const core::FieldValue& v) {
    if (f.live) out += (out.empty() ? "" : ", ") + f.key + " " + core::formatValue(v);
  });
  return out;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
