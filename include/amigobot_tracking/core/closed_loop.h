// Offline closed loop: the controller driving an ideal unicycle after a reference, with
// the target sampled at a chosen period. Shared by tests, the demo, the benchmark and the
// offline simulator.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "amigobot_tracking/core/controller.h"
#include "amigobot_tracking/core/reference.h"
#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace core {

struct ClosedLoopSetup {
  ControllerConfig controller;
  Pose2 initial_pose;
  std::vector<Disk> obstacles;
  double duration = 10.0;        // [s]
  double control_period = 1e-3;  // [s] controller step and integration step
  double sample_period = 0.0;    // [s] target sampling; 0 = every control step
};

// What an observer sees at every step: the state before the command is applied.
struct ClosedLoopStep {
  double t = 0.0;
  Pose2 pose;
  ReferenceState reference;
  ControllerOutput output;
};

struct ClosedLoopSummary {
  std::uint64_t steps = 0;
  double max_error_ratio = 0.0;      // max |e|/rho over the steps
  double final_error = 0.0;          // |e| at the end [m]
  double min_clearance_offset = 0.0; // disk of the effective radius around p_r [m]
  double min_clearance_body = 0.0;   // disk of radius R around the centre [m]
  std::uint64_t diamond_violations = 0;
  std::uint64_t invalid_steps = 0;   // NaN or unusable inputs
  std::uint64_t envelope_widenings = 0;
  std::uint64_t saturated_steps = 0;
};

using ClosedLoopObserver = std::function<void(const ClosedLoopStep&)>;

ClosedLoopSummary runClosedLoop(const ClosedLoopSetup& setup, const Reference& reference,
                                const ClosedLoopObserver& observer = {});

}  // namespace core
}  // namespace amigobot_tracking
