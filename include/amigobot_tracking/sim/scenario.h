// Scenario files of the offline simulator (YAML): robot, controller, reference,
// obstacles, simulation, optional target sensor and localization (robot pose timing).
// Parsed strictly: a missing or unknown key, a wrong type, an unknown reference type or
// an initial error outside rho(0) is refused with a message naming the file and the key, before anything runs.
// The format, key by key: config/scenarios/paper_5_2_rose.yaml.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/sim/closed_loop.h"
#include "amigobot_tracking/core/reference/reference_spec.h"

namespace amigobot_tracking {
namespace sim {

class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};


struct Scenario {
  std::string file;   // where it came from (for messages)
  std::string name;   // file stem, or simulation.name
  sim::ClosedLoopSetup setup;
  core::ReferenceSpec reference;  // the one reference description (reference_publisher's too)
  double log_period = 0.0;  // [s] CSV row spacing; 0 = every step
  std::string dynamics = "firmware";  // robot.dynamics: firmware | ideal (setup.dynamics.ideal)
  std::string robot_description;      // robot.description: a robot YAML for the firmware's values

  std::unique_ptr<core::Reference> makeReference() const;
};

// Reads and checks a scenario file. Throws ScenarioError("FILE:LINE: section.key: reason").
// `overrides`: "section.key=value" (amigobot_sim --set), applied before the checks: a value
// set so is checked like one in the file (unknown key, type, bounds).
Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from text; `file` only labels the messages.
Scenario parseScenario(const std::string& text, const std::string& file,
                       const std::vector<std::string>& overrides = {});
// The checks that need the whole scenario (controller and setup validation, |e(0)| < rho(0));
// parseScenario runs them, and callers that change a scenario (overrides, Monte Carlo) call
// them again. Throws ScenarioError.
void checkScenario(const Scenario& scenario);

// Names of the enumerations as in the YAML files.
std::string parseControlLaw(const std::string& name);  // a registry law (law_registry.h); throws std::invalid_argument
sim::VelocitySource parseVelocitySource(const std::string& name);  // throws std::invalid_argument
sim::Integrator parseIntegrator(const std::string& name);          // throws std::invalid_argument
std::string toString(sim::Integrator integrator);
std::string toString(sim::VelocitySource source);

}  // namespace sim
}  // namespace amigobot_tracking
