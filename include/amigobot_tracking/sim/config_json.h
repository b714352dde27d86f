// JSON of a config struct driven by its field table (core/support/field_table.h): one member per row
// under the row's key, '/' in a key nesting objects ("estimator/a1" -> {"estimator": {"a1"}}).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace core {

// Json: nlohmann::json or ordered_json (the reports keep the table's order).
template <class Json = nlohmann::json, class C>
Json fieldsToJson(const FieldTable<C>& table, const C& config) {
  Json out = Json::object();
  visitFields(table, config, [&](const Field<C>& f, const FieldValue& value) {
    Json* at = &out;
    std::string key = f.key;
    for (size_t slash = key.find('/'); slash != std::string::npos; slash = key.find('/')) {
      at = &(*at)[key.substr(0, slash)];
      key = key.substr(slash + 1);
    }
    std::visit([&](const auto& v) { (*at)[key] = v; }, value);
  });
  return out;
}

// Found by nlohmann's to_json lookup (argument-dependent: the namespace of ControllerConfig).
template <class Json>
void to_json(Json& j, const ControllerConfig& c) {
  j = fieldsToJson<Json>(controllerFields(), c);
}

}  // namespace core
}  // namespace amigobot_tracking
