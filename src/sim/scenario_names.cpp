// The YAML names of the scenario enumerations (controller.variant, controller.estimator,
// simulation.integrator).
#include <stdexcept>
#include <string>

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

constexpr Named<core::ControlLaw> kLaws[] = {
    {"paper", core::ControlLaw::kPaper}, {"fixed_rho", core::ControlLaw::kFixedRho},
    {"proportional", core::ControlLaw::kProportional}};
constexpr Named<core::VelocitySource> kSources[] = {
    {"paper", core::VelocitySource::kPaperEstimator}, {"finite_difference", core::VelocitySource::kFiniteDifference},
    {"kalman", core::VelocitySource::kKalman}};
constexpr Named<core::Integrator> kIntegrators[] = {
    {"explicit", core::Integrator::kExplicit}, {"band_implicit", core::Integrator::kBandImplicit},
    {"second_order", core::Integrator::kSecondOrder}};

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

core::ControlLaw parseControlLaw(const std::string& name) { return byName(kLaws, name, "controller variant"); }
core::VelocitySource parseVelocitySource(const std::string& name) { return byName(kSources, name, "estimator"); }
core::Integrator parseIntegrator(const std::string& name) { return byName(kIntegrators, name, "integrator"); }
std::string toString(core::ControlLaw law) { return nameOf(kLaws, law); }
std::string toString(core::VelocitySource source) { return nameOf(kSources, source); }
std::string toString(core::Integrator integrator) { return nameOf(kIntegrators, integrator); }

}  // namespace sim
}  // namespace amigobot_tracking
