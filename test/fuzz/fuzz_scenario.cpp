// libFuzzer target: the scenario file parser (sim/scenario.h parseScenario) on arbitrary
// YAML. Invariants: no crash or UB, no exception but ScenarioError, whose message starts
// with the file's name; an accepted scenario makes its reference, finite at t = 0.
#include <cstddef>
#include <cstdint>
#include <string>

#include "amigobot_tracking/sim/scenario.h"
#include "fuzz_support.h"

using namespace amigobot_tracking;
using fuzz_support::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sim::Scenario scenario;
  try {
    scenario = sim::parseScenario(text, "fuzz.yaml");
  } catch (const sim::ScenarioError& e) {
    check(std::string(e.what()).rfind("fuzz.yaml", 0) == 0);
    return 0;
  }
  check(scenario.makeReference()->at(0.0).position.allFinite());
  return 0;
}
