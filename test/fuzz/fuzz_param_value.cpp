// libFuzzer target: the field tables' value parser (core/support/field_table.h parseValue, the one
// reader of every parameter typed as text: rosparam strings, --set, reconfigure) on
// arbitrary text for each type. Invariants: no crash or UB; a parsed value formats to text
// that parses back to the same value, and checkValue answers for it against some bounds.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "amigobot_tracking/core/support/field_table.h"
#include "fuzz_support.h"

using namespace amigobot_tracking::core;
using fuzz_support::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const FieldType types[] = {FieldType::kReal, FieldType::kInteger, FieldType::kBoolean, FieldType::kText};
  const FieldType type = types[data[0] % 4];
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  FieldValue value;
  if (!parseValue(type, text, &value)) return 0;
  FieldValue again;
  const std::string written = formatValue(value);
  check(parseValue(type, written, &again));
  const double* d = std::get_if<double>(&value);
  if (d != nullptr && std::isnan(*d)) {
    check(std::isnan(std::get<double>(again)));
  } else {
    check(again == value);
  }
  Bounds bounds;
  bounds.min = 0.0;
  bounds.max = 1e6;
  bounds.choices = {"a", "b"};
  checkValue(type, bounds, value);
  return 0;
}
