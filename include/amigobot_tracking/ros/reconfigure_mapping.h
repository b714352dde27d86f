// dynamic_reconfigure <-> any config struct, by field name through the struct's field table
// (its live rows): the .cfg names the fields (cfg/Tracking.cfg: core::controllerFields();
// cfg/Driver.cfg: ros_layer::driverFields(), the client's rows and stamp_offset), nothing else lists them, and test_param_coverage
// checks that every .cfg entry is a live row of the same type and default, and the other way.
#pragma once

#include <string>
#include <variant>

#include <dynamic_reconfigure/Config.h>

#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace reconfigure_detail {

// "" when `field` is a live row of that type, else the error naming the entry.
std::string entryError(const std::string& name, bool found, bool live, bool same_type);

template <class C>
const core::Field<C>* liveField(const core::FieldTable<C>& table, const std::string& name, core::FieldType type,
                                std::string* error) {
  const core::Field<C>* f = core::findField(table, name);
  const std::string why = entryError(name, f != nullptr, f && f->live, f && f->type == type);
  if (why.empty()) return f;
  *error = why;
  return nullptr;
}

// Calls visit(field, entry value&) for every entry of the message, the field found by name.
template <class C, class Visit>
std::string forEachEntry(const core::FieldTable<C>& table, dynamic_reconfigure::Config& msg, Visit&& visit) {
  std::string error;
  for (auto& p : msg.doubles)
    if (auto* f = liveField(table, p.name, core::FieldType::kReal, &error)) visit(*f, p.value);
  for (auto& p : msg.ints)
    if (auto* f = liveField(table, p.name, core::FieldType::kInteger, &error)) visit(*f, p.value);
  for (auto& p : msg.bools)
    if (auto* f = liveField(table, p.name, core::FieldType::kBoolean, &error)) visit(*f, p.value);
  for (auto& p : msg.strs)
    if (auto* f = liveField(table, p.name, core::FieldType::kText, &error)) visit(*f, p.value);
  return error;
}

// An entry's value as the field's (the message's ints and bools have their own types).
template <class T>
core::FieldValue asField(core::FieldType type, const T& v) {
  switch (type) {
    case core::FieldType::kReal: return static_cast<double>(v);
    case core::FieldType::kInteger: return static_cast<int>(v);
    case core::FieldType::kBoolean: return static_cast<bool>(v);
    case core::FieldType::kText: break;
  }
  return core::FieldValue();
}
inline core::FieldValue asField(core::FieldType, const std::string& v) { return v; }

template <class T>
void assign(const core::FieldValue& v, T* out) {
  if (const double* d = std::get_if<double>(&v)) *out = static_cast<T>(*d);
  if (const int* i = std::get_if<int>(&v)) *out = static_cast<T>(*i);
  if (const bool* b = std::get_if<bool>(&v)) *out = static_cast<T>(*b);
}
inline void assign(const core::FieldValue& v, std::string* out) { *out = std::get<std::string>(v); }

}  // namespace reconfigure_detail

// Sets every field named by an entry of `config` (a generated XConfig) on *out (no bounds
// check: the caller validates). "" or "reconfigure entry 'x' is no live field ...".
template <class Reconfigure, class C>
std::string applyReconfigure(const Reconfigure& config, const core::FieldTable<C>& table, C* out) {
  dynamic_reconfigure::Config msg;
  config.__toMessage__(msg);
  return reconfigure_detail::forEachEntry(table, msg, [&](const core::Field<C>& f, const auto& value) {
    f.set(*out, reconfigure_detail::asField(f.type, value));
  });
}

// Writes the values of `in` into the entries of *config (same names).
template <class C, class Reconfigure>
std::string fillReconfigure(const core::FieldTable<C>& table, const C& in, Reconfigure* config) {
  dynamic_reconfigure::Config msg;
  config->__toMessage__(msg);
  const std::string error = reconfigure_detail::forEachEntry(
      table, msg, [&](const core::Field<C>& f, auto& value) { reconfigure_detail::assign(f.get(in), &value); });
  config->__fromMessage__(msg);
  return error;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
