// One description per parameter set: a table of the fields of a config struct (key, unit,
// meaning, type, bounds, live-reconfigurable) that every reader and writer walks, so a field
// is named once. Keys are ROS-style paths ('/' between nesting levels: "estimator/a1"), the
// same in ROS parameters, scenario files, dynamic_reconfigure, JSON and --set. Defaults are
// read from a default-constructed struct, never written a second time. Std only.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace amigobot_tracking {
namespace core {

enum class FieldType { kReal, kInteger, kBoolean, kText };
using FieldValue = std::variant<double, int, bool, std::string>;

// Allowed values: an interval for numbers (NaN never; +-inf only when !finite), a list of
// choices for text (empty: any text).
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  bool min_open = false;
  double max = std::numeric_limits<double>::infinity();
  bool max_open = false;
  bool finite = true;
  std::vector<std::string> choices;
};

inline Bounds anyValue() { return Bounds(); }  // finite, any number
inline Bounds interval(double min, bool min_open, double max, bool max_open) {
  Bounds b;
  b.min = min;
  b.min_open = min_open;
  b.max = max;
  b.max_open = max_open;
  return b;
}
inline Bounds positive() { return interval(0.0, true, std::numeric_limits<double>::infinity(), false); }
inline Bounds nonNegative() { return interval(0.0, false, std::numeric_limits<double>::infinity(), false); }
// Safety ceilings: a timeout or radius beyond these is a typo (1e308 once reached a robot),
// never a setting. A minute without input is not "still fresh"; no AmigoBot disk is 100 m.
constexpr double kMaxTimeout = 60.0;  // [s]
constexpr double kMaxRadius = 100.0;  // [m]
inline Bounds boundedTimeout() { return interval(0.0, true, kMaxTimeout, false); }
inline Bounds boundedTimeoutOrOff() { return interval(0.0, false, kMaxTimeout, false); }  // 0 = off
inline Bounds boundedRadius() { return interval(0.0, true, kMaxRadius, false); }
inline Bounds boundedRadiusOrOff() { return interval(0.0, false, kMaxRadius, false); }  // 0 = off
// A period, timeout or delay [s]: at most a day, so ros::Duration (32-bit seconds), timers
// and sleeps hold it and its inverse rate; > 0 (or >= 0 where 0 means "off").
constexpr double kMaxDuration = 86400.0;
inline Bounds duration() { return interval(0.0, true, kMaxDuration, false); }
inline Bounds durationOrZero() { return interval(0.0, false, kMaxDuration, false); }
inline Bounds atLeast(double min) { return interval(min, false, std::numeric_limits<double>::infinity(), false); }
inline Bounds oneOf(std::vector<std::string> choices) {
  Bounds b;
  b.choices = std::move(choices);
  return b;
}
inline Bounds allowInfinite(Bounds b) {
  b.finite = false;
  return b;
}

template <class C>
struct Field {
  std::string key;      // "k_d", "estimator/a1"
  std::string unit;     // "m/s"; "-" when dimensionless
  std::string meaning;  // one line
  FieldType type = FieldType::kReal;
  Bounds bounds;
  bool live = false;  // changeable at run time (dynamic_reconfigure)
  std::function<FieldValue(const C&)> get;
  std::function<void(C&, const FieldValue&)> set;  // the value has the field's type
  // The default as the docs and YAML comments say it when the struct's is not the whole story
  // ("the robot file's v_max"); empty: the default-constructed struct's value.
  std::string default_text;
  // Live rows: dynamic_reconfigure's range (the generated .cfg's min and max).
  double reconfigure_min = 0.0, reconfigure_max = 0.0;
};

template <class C>
using FieldTable = std::vector<Field<C>>;

namespace detail {
template <class T>
constexpr FieldType typeOf();
template <>
constexpr FieldType typeOf<double>() { return FieldType::kReal; }
template <>
constexpr FieldType typeOf<int>() { return FieldType::kInteger; }
template <>
constexpr FieldType typeOf<bool>() { return FieldType::kBoolean; }
template <>
constexpr FieldType typeOf<std::string>() { return FieldType::kText; }
}  // namespace detail

// A row for the member `member` of C (double, int, bool or std::string).
template <class C, class T>
Field<C> field(std::string key, T C::*member, std::string unit, std::string meaning, Bounds bounds = {}) {
  Field<C> f;
  f.key = std::move(key);
  f.unit = std::move(unit);
  f.meaning = std::move(meaning);
  f.type = detail::typeOf<T>();
  f.bounds = std::move(bounds);
  f.get = [member](const C& c) { return FieldValue(c.*member); };
  f.set = [member](C& c, const FieldValue& v) { c.*member = std::get<T>(v); };
  return f;
}

// The same row, changeable at run time between `min` and `max` (dynamic_reconfigure's range,
// written into the generated .cfg; the bounds still judge every value).
template <class C>
Field<C> live(Field<C> f, double min, double max) {
  f.live = true;
  f.reconfigure_min = min;
  f.reconfigure_max = max;
  return f;
}

// The same row, its default described as `text` in the generated docs and YAML comments.
template <class C>
Field<C> defaultText(Field<C> f, std::string text) {
  f.default_text = std::move(text);
  return f;
}

// `row` of the struct S, as a row of C that holds S as `member`, its key under `prefix`: a
// sub-struct's field keeps its place and its name in C's table.
template <class C, class S>
Field<C> nested(S C::*member, const Field<S>& row, const std::string& prefix = "") {
  Field<C> f;
  f.key = prefix + row.key;
  f.unit = row.unit;
  f.meaning = row.meaning;
  f.type = row.type;
  f.bounds = row.bounds;
  f.live = row.live;
  f.default_text = row.default_text;
  f.reconfigure_min = row.reconfigure_min;
  f.reconfigure_max = row.reconfigure_max;
  f.get = [member, get = row.get](const C& c) { return get(c.*member); };
  f.set = [member, set = row.set](C& c, const FieldValue& v) { set(c.*member, v); };
  return f;
}

// Appends `sub`'s rows for the member `member` of C under `prefix` ("estimator/").
template <class C, class S>
void include(FieldTable<C>* into, const std::string& prefix, S C::*member, const FieldTable<S>& sub) {
  for (const Field<S>& s : sub) into->push_back(nested(member, s, prefix));
}

// Appends the rows of B, a base class of C that C extends (the robot description that
// aria::RobotParams extends), keys unchanged.
template <class C, class B>
void includeBase(FieldTable<C>* into, const FieldTable<B>& base) {
  for (const Field<B>& b : base) {
    Field<C> f = {b.key, b.unit, b.meaning, b.type, b.bounds, b.live, {}, {}, b.default_text, b.reconfigure_min, b.reconfigure_max};
    f.get = [get = b.get](const C& c) { return get(static_cast<const B&>(c)); };
    f.set = [set = b.set](C& c, const FieldValue& v) { set(static_cast<B&>(c), v); };
    into->push_back(std::move(f));
  }
}

// "a number", "an integer", "true or false", "a text".
std::string typeName(FieldType type);
// "> 0", "in (0, 1]", "one of a, b", "" for any value.
std::string describeBounds(FieldType type, const Bounds& bounds);
// "" when `value` is allowed, else "must be ..., got ..." (without the key).
std::string checkValue(FieldType type, const Bounds& bounds, const FieldValue& value);
// The value as written in YAML/--set ("0.15", "true", "map"); reals to full precision.
std::string formatValue(const FieldValue& value);
// Parses text of the given type ("3" is a real too; booleans: true/false). False on bad text.
bool parseValue(FieldType type, const std::string& text, FieldValue* out);

template <class C>
const Field<C>* findField(const FieldTable<C>& table, const std::string& key) {
  for (const Field<C>& f : table)
    if (f.key == key) return &f;
  return nullptr;
}

// "" when every field is within its bounds, else "key: reason" for the first that is not.
template <class C>
std::string checkFields(const FieldTable<C>& table, const C& config) {
  for (const Field<C>& f : table) {
    const std::string why = checkValue(f.type, f.bounds, f.get(config));
    if (!why.empty()) return f.key + ": " + why;
  }
  return "";
}

// Sets one field from text (`--set`): "" or "key: reason" (unknown key, bad text, out of bounds).
template <class C>
std::string setField(const FieldTable<C>& table, const std::string& key, const std::string& text, C* config) {
  const Field<C>* f = findField(table, key);
  if (!f) return key + ": unknown key";
  FieldValue value;
  if (!parseValue(f->type, text, &value)) return key + ": expected " + typeName(f->type) + ", got '" + text + "'";
  const std::string why = checkValue(f->type, f->bounds, value);
  if (!why.empty()) return key + ": " + why;
  f->set(*config, value);
  return "";
}

// A key set that no reader uses (a typo, a parameter of another driver), with the nearest
// key the node reads ("" when none is within a third of the key's length in edits).
struct UnknownKey {
  std::string key;
  std::string nearest;
};
// The keys of `present` that are none of `known`; a known key also covers the keys under it
// ("virtual_obstacles" covers "virtual_obstacles/0/id"). Sorted as `present`.
std::vector<UnknownKey> unknownKeys(const std::vector<std::string>& present, const std::vector<std::string>& known);

// Calls visit(field, value) for every row, in table order (loggers, JSON).
template <class C, class Visit>
void visitFields(const FieldTable<C>& table, const C& config, Visit&& visit) {
  for (const Field<C>& f : table) visit(f, f.get(config));
}

// Copies the live rows (what reconfigure may change) of `from` into *to.
template <class C>
void copyLiveFields(const FieldTable<C>& table, const C& from, C* to) {
  for (const Field<C>& f : table)
    if (f.live) f.set(*to, f.get(from));
}

// True when every live row has the same value in a and b.
template <class C>
bool sameLiveFields(const FieldTable<C>& table, const C& a, const C& b) {
  for (const Field<C>& f : table)
    if (f.live && !(f.get(a) == f.get(b))) return false;
  return true;
}

// "k_d 0.15, k_o 1, ..." over the live rows, for the log.
template <class C>
std::string describeLiveFields(const FieldTable<C>& table, const C& config) {
  std::string out;
  for (const Field<C>& f : table)
    if (f.live) out += (out.empty() ? "" : ", ") + f.key + " " + formatValue(f.get(config));
  return out;
}

// The value of the row in a default-constructed C.
template <class C>
FieldValue defaultValue(const Field<C>& f) {
  return f.get(C());
}

}  // namespace core
}  // namespace amigobot_tracking
