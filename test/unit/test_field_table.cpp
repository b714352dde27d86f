// The field tables' generic operations: bounds check naming the key, --set from text,
// visiting, nested tables under a prefix, defaults from a default-constructed struct.
#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <map>

#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/sim/config_json.h"

using namespace amigobot_tracking::core;

namespace {

struct Inner {
  double gain = 2.0;
};

struct Demo {
  double rate = 20.0;
  int count = 3;
  bool on = false;
  std::string mode = "fast";
  Inner inner;
};

FieldTable<Inner> innerTable() {
  return {defaultText(field("gain", &Inner::gain, "1/s", "a gain", positive()), "two")};
}

FieldTable<Demo> demoTable() {
  FieldTable<Demo> t = {
      live(field("rate", &Demo::rate, "Hz", "a rate", interval(0.0, true, 100.0, false)), 0.0, 100.0),
      field("count", &Demo::count, "-", "a count", atLeast(1)),
      field("on", &Demo::on, "-", "a switch"),
      field("mode", &Demo::mode, "-", "a mode", oneOf({"fast", "slow"})),
  };
  include(&t, "inner/", &Demo::inner, innerTable());
  return t;
}

}  // namespace

TEST(FieldTable, ChecksBoundsAndNamesTheKey) {
  const FieldTable<Demo> t = demoTable();
  Demo d;
  EXPECT_EQ(checkFields(t, d), "");
  d.rate = 0.0;
  EXPECT_EQ(checkFields(t, d), "rate: must be a finite number in (0, 100], got 0");
  d.rate = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(checkFields(t, d).rfind("rate: ", 0), 0u);
  d = Demo();
  d.count = 0;
  EXPECT_EQ(checkFields(t, d), "count: must be >= 1, got 0");
  d = Demo();
  d.mode = "medium";
  EXPECT_EQ(checkFields(t, d), "mode: must be one of fast, slow, got 'medium'");
  d = Demo();
  d.inner.gain = -1.0;
  EXPECT_EQ(checkFields(t, d), "inner/gain: must be a finite number > 0, got -1");
}

TEST(FieldTable, SetsFromTextWithTypeAndBounds) {
  const FieldTable<Demo> t = demoTable();
  Demo d;
  EXPECT_EQ(setField(t, "rate", "50", &d), "");
  EXPECT_EQ(d.rate, 50.0);
  EXPECT_EQ(setField(t, "inner/gain", "0.25", &d), "");
  EXPECT_EQ(d.inner.gain, 0.25);
  EXPECT_EQ(setField(t, "on", "true", &d), "");
  EXPECT_TRUE(d.on);
  EXPECT_EQ(setField(t, "count", "2.5", &d), "count: expected an integer, got '2.5'");
  EXPECT_EQ(setField(t, "on", "yes", &d), "on: expected true or false, got 'yes'");
  EXPECT_EQ(setField(t, "rate", "fast", &d), "rate: expected a number, got 'fast'");
  EXPECT_EQ(setField(t, "rate", "500", &d), "rate: must be a finite number in (0, 100], got 500");
  EXPECT_EQ(d.rate, 50.0) << "a refused value must leave the field unchanged";
  EXPECT_EQ(setField(t, "rat", "5", &d), "rat: unknown key");
}

TEST(FieldTable, VisitsEveryRowInOrderWithDefaults) {
  const FieldTable<Demo> t = demoTable();
  std::vector<std::string> seen;
  Demo d;
  d.count = 7;
  visitFields(t, d, [&](const Field<Demo>& f, const FieldValue& v) { seen.push_back(f.key + "=" + formatValue(v)); });
  EXPECT_EQ(seen, (std::vector<std::string>{"rate=20", "count=7", "on=false", "mode=fast", "inner/gain=2"}));
  EXPECT_EQ(std::get<int>(defaultValue(t[1])), 3) << "the default comes from Demo{}, not from d";
  EXPECT_TRUE(t[0].live);
  EXPECT_FALSE(t[1].live);
  EXPECT_EQ(t[0].reconfigure_max, 100.0);
  // A nested row keeps what the generated docs and .cfg read: its default's words, its range.
  EXPECT_EQ(t[4].default_text, "two");
  const Field<Demo> ranged = nested(&Demo::inner, live(innerTable()[0], 0.5, 4.0), "x/");
  EXPECT_TRUE(ranged.live);
  EXPECT_EQ(ranged.reconfigure_min, 0.5);
  EXPECT_EQ(ranged.reconfigure_max, 4.0);
  EXPECT_EQ(ranged.default_text, "two");
}

// What reconfigure changes: the live rows only (here "rate"), compared and logged the same way.
TEST(FieldTable, CopiesComparesAndDescribesTheLiveRowsOnly) {
  const FieldTable<Demo> t = demoTable();
  Demo from, to;
  from.rate = 42.0;
  from.count = 9;
  EXPECT_FALSE(sameLiveFields(t, from, to));
  copyLiveFields(t, from, &to);
  EXPECT_EQ(to.rate, 42.0);
  EXPECT_EQ(to.count, 3) << "a row that is not live is never copied";
  EXPECT_TRUE(sameLiveFields(t, from, to)) << "count differs, but it is not live";
  EXPECT_EQ(describeLiveFields(t, to), "rate 42");
}

TEST(FieldTable, FormatsRealsShortestExact) {
  EXPECT_EQ(formatValue(0.15), "0.15");
  EXPECT_EQ(formatValue(1e-3), "0.001");
  EXPECT_EQ(formatValue(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(formatValue(0.1 + 0.2), "0.30000000000000004") << "17 digits where 15 and 16 do not read back";
  EXPECT_EQ(formatValue(300.0), "300");
  EXPECT_EQ(formatValue(-2.5e-7), "-2.5e-07");
  EXPECT_EQ(formatValue(std::numeric_limits<double>::infinity()), "inf");
  for (const double v : {0.1 + 0.2, 1.0 / 3.0, 2.0 / 3.0, 6.02214076e23, 1e-300, 0.15, 1.0 - 1e-16})
    EXPECT_EQ(std::strtod(formatValue(v).c_str(), nullptr), v) << formatValue(v);
}

TEST(FieldTable, ControllerTableHasUniqueKeysAndValidDefaults) {
  std::map<std::string, int> count;
  for (const auto& f : controllerFields()) ++count[f.key];
  for (const auto& [key, n] : count) EXPECT_EQ(n, 1) << key;
  EXPECT_EQ(count.count("estimator/a1"), 1u);
  EXPECT_EQ(checkFields(controllerFields(), ControllerConfig()), "");
}

TEST(FieldTable, JsonNestsBySlash) {
  ControllerConfig c;
  c.k_d = 2.5;
  const nlohmann::json j = c;
  EXPECT_EQ(j.at("k_d").get<double>(), 2.5);
  EXPECT_EQ(j.at("estimator").at("a1").get<double>(), c.estimator.a1);
  EXPECT_EQ(j.at("body_safe").get<bool>(), c.body_safe);
  // A text with quotes and backslashes stays valid JSON.
  const nlohmann::json path = std::string("a \"b\" \\c");
  EXPECT_EQ(nlohmann::json::parse(path.dump()).get<std::string>(), "a \"b\" \\c");
}

TEST(FieldTable, UnknownKeysNamedWithTheNearestKnownKey) {
  const std::vector<std::string> known = {"port", "baud", "ticks_mm", "base_frame", "virtual_obstacles"};
  const std::vector<UnknownKey> u =
      unknownKeys({"port", "serial_port", "tiks_mm", "virtual_obstacles/0/id", "Baud", "enable_button"}, known);
  ASSERT_EQ(u.size(), 4u);
  EXPECT_EQ(u[0].key, "serial_port");
  EXPECT_EQ(u[0].nearest, "") << "5 edits from port: too far to suggest";
  EXPECT_EQ(u[1].key, "tiks_mm");
  EXPECT_EQ(u[1].nearest, "ticks_mm");
  EXPECT_EQ(u[2].key, "Baud") << "keys are case-sensitive: Baud is not baud";
  EXPECT_EQ(u[2].nearest, "baud");
  EXPECT_EQ(u[3].key, "enable_button");
  EXPECT_TRUE(unknownKeys({"virtual_obstacles_x"}, known).size() == 1u) << "a prefix covers only keys under it";
}
