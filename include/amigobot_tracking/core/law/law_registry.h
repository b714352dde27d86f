// The one list of control laws: each law's name (the same in the tracking node's `law`, the
// scenario's controller.variant, amigobot_sim --variant, recorded runs and the docs), what it
// is, the facts the tools need about it, and how to build it. A new law is its class and one
// line in law_registry.cpp.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "amigobot_tracking/core/law/control_law.h"

namespace amigobot_tracking {
namespace core {

// What a law is built from.
struct LawSetup {
  ControllerConfig controller;
  double proportional_gain = 30.0;  // [1/s] k_p of the proportional baseline
};

using LawFactory = std::function<std::unique_ptr<ControlLaw>(const LawSetup&)>;

struct LawEntry {
  std::string name;
  std::string summary;         // one line for --help and the docs
  bool has_rho_bound = false;  // rho is a performance bound: |e|/rho is scored, |e(0)| < rho_0 is required
  bool on_robot = false;       // the tracking node runs it (a value of ControllerConfig::law); the
                               // simulator runs it inside the node's own loop (core::TrackingLoop)
  bool band_implicit = false;  // its avoidance is the explicit (10): the simulator's band-implicit step applies
  bool obstacle_velocities = false;  // its avoidance uses a disk's velocity whenever the disk carries one;
                                    // the others only with moving_obstacles (ControllerConfig::obstacleVelocities)
  std::string provider;        // the library that builds it
  LawFactory factory;          // empty until a provider above core registers it (provideLaw)
};

// A name kept for old files and command lines: it still works, with a deprecation warning.
struct LawAlias {
  std::string name;
  std::string law;      // the registry name it stands for
  std::string variant;  // the configuration of that law it meant
};

const std::vector<LawEntry>& lawEntries();
const std::vector<LawAlias>& lawAliases();
// nullptr when `name` is no law's name.
const LawEntry* findLaw(const std::string& name);
const LawAlias* findLawAlias(const std::string& name);
// Every law's name, in the registry's order; and those the tracking node runs.
std::vector<std::string> lawNames();
std::vector<std::string> robotLawNames();
// "a, b, c": for error messages and --help.
std::string lawNameList(const std::vector<std::string>& names);

// Builds the law `name`. Throws std::invalid_argument naming the known laws for an unknown
// name, or the provider for a law whose library has not registered it.
std::unique_ptr<ControlLaw> makeLaw(const std::string& name, const LawSetup& setup);
// A library above core registers the factory of its law (which must be in the list); returns
// the one it replaces (empty the first time). Not thread-safe: call it before running laws.
LawFactory provideLaw(const std::string& name, LawFactory factory);

}  // namespace core
}  // namespace amigobot_tracking
