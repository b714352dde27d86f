// JSON of a config struct driven by its field table (core/field_table.h): one member per row
// under the row's key, '/' in a key nesting objects ("estimator/a1" -> {"estimator": {"a1"}}).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "amigobot_tracking/core/controller_config.h"
#include "amigobot_tracking/core/field_table.h"

namespace amigobot_tracking {
namespace core {

template <class C>
nlohmann::json fieldsToJson(const FieldTable<C>& table, const C& config) {
  nlohmann::json out = nlohmann::json::object();
  visitFields(table, config, [&](const Field<C>& f, const FieldValue& value) {
    nlohmann::json* at = &out;
    std::string key = f.key;
    for (size_t slash = key.find('/'); slash != std::string::npos; slash = key.find('/')) {
      at = &(*at)[key.substr(0, slash)];
      key = key.substr(slash + 1);
    }
    std::visit([&](const auto& v) { (*at)[key] = v; }, value);
  });
  return out;
}

inline void to_json(nlohmann::json& j, const ControllerConfig& c) { j = fieldsToJson(controllerFields(), c); }

}  // namespace core
}  // namespace amigobot_tracking
