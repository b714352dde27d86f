// A peer for Table 2: MRPT's reactive navigator (CReactiveNavigationSystem: differential-drive
// TP-space PTGs and a holonomic method) re-targeted at the moving target every navigation period,
// run by the offline closed loop as controller.variant mrpt_reactive.
//
// Its robot (CRobot2NavInterface) is the simulator's unicycle: the pose the closed loop gives,
// the simulated time as MRPT's clock (mrpt::Clock switched to Simulated during a run), and the
// disks seen as a laser sees them: a ray-cast scan from the robot centre turned into a point
// cloud. Every (v, w) it sends passes through the project's diamond (12) before it is applied,
// so no command leaves it. MRPT drives the robot centre to the target and ends a navigation
// within the offset r (where the offset point reaches the target); the metrics score the
// offset point like every other law.
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/law/law_registry.h"

namespace amigobot_tracking {
namespace sim_mrpt {

struct ReactiveLawOptions {
  double period = 0.05;                   // [s] navigation step: re-target + navigationStep (20 Hz, the node's rate)
  std::string holonomic = "CHolonomicND"; // CHolonomicND | CHolonomicVFF | CHolonomicFullEval
  double ref_distance = 4.0;              // [m] PTG horizon (obstacles farther are ignored)
  double ptg_resolution = 0.05;           // [m] PTG collision-grid cell
  int ptg_paths = 121;                    // trajectories per PTG
  int beams = 360;                        // laser beams over 360 deg
  double range_max = 8.0;                 // [m] laser range (sim_laser's default)
  // Compile MRPT's score formulas on a point in PTG 0's domain before the first step (see
  // reactive_law.cpp); false shows MRPT 2.5's own failure on a target outside that domain.
  bool prime_scores = true;
};

// The navigator's configuration (MRPT INI text) for these limits and robot: PTGs C forward,
// alpha, C backward; robot shape a 16-gon around the body disk of radius R; v_max, w_max the
// diamond's corners.
std::string reactiveConfigText(const core::ControllerConfig& config, const ReactiveLawOptions& options);

// A navigator error (MRPT's NAV_ERROR: an exception inside it, an emergency stop) makes step()
// throw std::runtime_error naming MRPT's reason: the run fails instead of scoring a robot that
// stopped. Laws may live on several threads (Monte Carlo): MRPT's process-wide clock is
// simulated while any lives. A core::ControlLaw named mrpt_reactive in the law registry.
std::unique_ptr<core::ControlLaw> makeReactiveLaw(const core::LawSetup& setup,
                                                  const ReactiveLawOptions& options = ReactiveLawOptions());
core::LawFactory reactiveLawFactory(const ReactiveLawOptions& options = ReactiveLawOptions());
// Registers the factory as the registry's mrpt_reactive (core::provideLaw): a program that links
// this library calls it once at its start (amigobot_sim does); returns the factory it replaces.
core::LawFactory provideReactiveLaw(const ReactiveLawOptions& options = ReactiveLawOptions());

}  // namespace sim_mrpt
}  // namespace amigobot_tracking
