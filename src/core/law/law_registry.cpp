#include "amigobot_tracking/core/law/law_registry.h"

#include <stdexcept>

#include "amigobot_tracking/core/law/paper_controller.h"
#include "amigobot_tracking/core/law/proportional_controller.h"
#include "amigobot_tracking/core/law/recommended_controller.h"

namespace amigobot_tracking {
namespace core {
namespace {

std::vector<LawEntry>& entries() {
  static std::vector<LawEntry> list = {
      // name, summary, has_rho_bound, on_robot, band_implicit, obstacle_velocities, provider, factory
      {"recommended", "the recommended law: navigation field, safety filter over the diamond, (13')", true, true,
       false, true, "core", [](const LawSetup& s) { return std::make_unique<RecommendedController>(s.controller); }},
      {"paper", "the paper's law, eqs. (9)-(13)", true, true, true, false, "core",
       [](const LawSetup& s) { return std::make_unique<PaperController>(s.controller); }},
      {"fixed_rho", "the paper's (9)-(12) with rho following the prescribed decay only (no adaptation)", true,
       true, true, false, "core",
       [](const LawSetup& s) { return std::make_unique<PaperController>(s.controller, true); }},
      {"proportional", "baseline: feedback linearisation + k_p e + the same u_c and saturation", false, false,
       false, false, "core",
       [](const LawSetup& s) { return std::make_unique<ProportionalController>(s.controller, s.proportional_gain); }},
      {"mrpt_reactive", "peer: MRPT's CReactiveNavigationSystem re-targeted at the target", false, false, false,
       false, "sim_mrpt", nullptr},
  };
  return list;
}

}  // namespace

const std::vector<LawEntry>& lawEntries() { return entries(); }

const std::vector<LawAlias>& lawAliases() {
  // Recorded runs labelled the paper's law with its tangential escape "escape".
  static const std::vector<LawAlias> aliases = {{"escape", "paper", "tangential_avoidance"}};
  return aliases;
}

const LawEntry* findLaw(const std::string& name) {
  for (const LawEntry& e : entries())
    if (e.name == name) return &e;
  return nullptr;
}

const LawAlias* findLawAlias(const std::string& name) {
  for (const LawAlias& a : lawAliases())
    if (a.name == name) return &a;
  return nullptr;
}

std::vector<std::string> lawNames() {
  std::vector<std::string> names;
  for (const LawEntry& e : entries()) names.push_back(e.name);
  return names;
}

std::vector<std::string> robotLawNames() {
  std::vector<std::string> names;
  for (const LawEntry& e : entries())
    if (e.on_robot) names.push_back(e.name);
  return names;
}

std::string lawNameList(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

std::unique_ptr<ControlLaw> makeLaw(const std::string& name, const LawSetup& setup) {
  const LawEntry* entry = findLaw(name);
  if (!entry) throw std::invalid_argument("law: unknown law '" + name + "' (known: " + lawNameList(lawNames()) + ")");
  if (!entry->factory)
    throw std::invalid_argument("law: " + name + " is provided by the " + entry->provider +
                                " library, which has not registered it in this program (amigobot_sim does)");
  return entry->factory(setup);
}

LawFactory provideLaw(const std::string& name, LawFactory factory) {
  for (LawEntry& e : entries())
    if (e.name == name) {
      std::swap(e.factory, factory);
      return factory;
    }
  throw std::invalid_argument("provideLaw: '" + name + "' is not in the law registry");
}

}  // namespace core
}  // namespace amigobot_tracking
