#include "amigobot_tracking/core/support/field_table.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace amigobot_tracking {
namespace core {
namespace {

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

double asNumber(const FieldValue& v) {
  if (const double* d = std::get_if<double>(&v)) return *d;
  if (const int* i = std::get_if<int>(&v)) return *i;
  return 0.0;
}

// Edits (insert, delete, substitute; case-insensitive) turning a into b.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

bool covers(const std::string& known, const std::string& key) {
  return key == known || (key.size() > known.size() && key.compare(0, known.size(), known) == 0 && key[known.size()] == '/');
}

}  // namespace

std::vector<UnknownKey> unknownKeys(const std::vector<std::string>& present, const std::vector<std::string>& known) {
  std::vector<UnknownKey> out;
  for (const std::string& key : present) {
    if (std::any_of(known.begin(), known.end(), [&](const std::string& k) { return covers(k, key); })) continue;
    UnknownKey u{key, ""};
    std::size_t best = key.size() / 3 + 1;  // farther than this is no suggestion
    for (const std::string& k : known) {
      const std::size_t d = editDistance(key, k);
      if (d < best) best = d, u.nearest = k;
    }
    out.push_back(u);
  }
  return out;
}

std::string typeName(FieldType type) {
  switch (type) {
    case FieldType::kReal: return "a number";
    case FieldType::kInteger: return "an integer";
    case FieldType::kBoolean: return "true or false";
    case FieldType::kText: return "a text";
  }
  return "?";
}

std::string describeBounds(FieldType type, const Bounds& b) {
  if (type == FieldType::kText) return b.choices.empty() ? "" : "one of " + joined(b.choices);
  if (type == FieldType::kBoolean) return "";
  const bool low = std::isfinite(b.min), high = std::isfinite(b.max);
  if (low && high) {
    return std::string("in ") + (b.min_open ? "(" : "[") + number(b.min) + ", " + number(b.max) +
           (b.max_open ? ")" : "]");
  }
  if (low) return (b.min_open ? "> " : ">= ") + number(b.min);
  if (high) return (b.max_open ? "< " : "<= ") + number(b.max);
  return "";
}

std::string checkValue(FieldType type, const Bounds& b, const FieldValue& value) {
  if (type == FieldType::kBoolean) return "";
  if (type == FieldType::kText) {
    const std::string& text = std::get<std::string>(value);
    for (const std::string& c : b.choices)
      if (c == text) return "";
    return b.choices.empty() ? "" : "must be " + describeBounds(type, b) + ", got '" + text + "'";
  }
  const double v = asNumber(value);
  const bool finite_ok = b.finite ? std::isfinite(v) : !std::isnan(v);
  const bool low_ok = b.min_open ? v > b.min : v >= b.min;
  const bool high_ok = b.max_open ? v < b.max : v <= b.max;
  if (finite_ok && low_ok && high_ok) return "";
  const std::string range = describeBounds(type, b);
  const std::string what = type == FieldType::kInteger ? "" : b.finite ? "a finite number" : "a number";
  std::string must = what;
  if (!range.empty()) must += (must.empty() ? "" : " ") + range;
  return "must be " + must + ", got " + formatValue(value);
}

std::string formatValue(const FieldValue& value) {
  std::ostringstream out;
  if (const double* d = std::get_if<double>(&value)) {
    // The shortest of %.15g, %.16g, %.17g that reads back to the same double (0.15, not
    // 0.14999999999999999; 17 digits always do). Not std::to_chars: floating-point to_chars
    // needs libstdc++ 11, Noetic's Ubuntu 20.04 has GCC 9 (scripts/test/check_cxx_features.py).
    char text[32];
    for (int digits = 15; digits <= 17; ++digits) {
      std::snprintf(text, sizeof text, "%.*g", digits, *d);
      if (std::strtod(text, nullptr) == *d || !std::isfinite(*d)) break;
    }
    out << text;
  } else if (const int* i = std::get_if<int>(&value)) {
    out << *i;
  } else if (const bool* b = std::get_if<bool>(&value)) {
    out << (*b ? "true" : "false");
  } else {
    out << std::get<std::string>(value);
  }
  return out.str();
}

bool parseValue(FieldType type, const std::string& text, FieldValue* out) {
  if (type == FieldType::kText) {
    *out = text;
    return true;
  }
  if (type == FieldType::kBoolean) {
    if (text != "true" && text != "false") return false;
    *out = text == "true";
    return true;
  }
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  if (type == FieldType::kInteger) {
    const long v = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      return false;
    *out = static_cast<int>(v);
    return true;
  }
  const double v = std::strtod(text.c_str(), &end);
  if (*end != '\0') return false;
  *out = v;
  return true;
}

}  // namespace core
}  // namespace amigobot_tracking
