// The YAML names of the scenario enumerations (controller.estimator, simulation.integrator)
// and the check of controller.variant against the law registry.
#include <stdexcept>
#include <string>

#include "amigobot_tracking/core/law/law_registry.h"
#include "amigobot_tracking/sim/scenario.h"

namespace amigobot_tracking {
namespace sim {
namespace {

// The YAML names of an enumeration, in the order the messages list them.
template <typename E>
struct Named {
  const char* name;
  E value;
};

constexpr Named<sim::VelocitySource> kSources[] = {
    {"paper", sim::VelocitySource::kPaperEstimator}, {"finite_difference", sim::VelocitySource::kFiniteDifference},
    {"kalman", sim::VelocitySource::kKalman}};
constexpr Named<sim::Integrator> kIntegrators[] = {
    {"explicit", sim::Integrator::kExplicit}, {"band_implicit", sim::Integrator::kBandImplicit},
    {"second_order", sim::Integrator::kSecondOrder}};

// Throws std::invalid_argument("unknown WHAT 'name' (choice, choice, ...)").
template <typename E, size_t N>
E byName(const Named<E> (&table)[N], const std::string& name, const std::string& what) {
  std::string choices;
  for (const Named<E>& n : table) {
    if (name == n.name) return n.value;
    choices += (choices.empty() ? "" : ", ") + std::string(n.name);
  }
  throw std::invalid_argument("unknown " + what + " '" + name + "' (" + choices + ")");
}

template <typename E, size_t N>
std::string nameOf(const Named<E> (&table)[N], E value) {
  for (const Named<E>& n : table)
    if (n.value == value) return n.name;
  return "?";
}

}  // namespace

std::string parseControlLaw(const std::string& name) {
  if (!core::findLaw(name))
    throw std::invalid_argument("unknown controller variant '" + name + "' (" + core::lawNameList(core::lawNames()) + ")");
  return name;
}
sim::VelocitySource parseVelocitySource(const std::string& name) { return byName(kSources, name, "estimator"); }
sim::Integrator parseIntegrator(const std::string& name) { return byName(kIntegrators, name, "integrator"); }
std::string toString(sim::VelocitySource source) { return nameOf(kSources, source); }
std::string toString(sim::Integrator integrator) { return nameOf(kIntegrators, integrator); }

}  // namespace sim
}  // namespace amigobot_tracking
