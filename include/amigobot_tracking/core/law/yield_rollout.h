// The recommended law's look-ahead for people it cannot outrun: when the safety filter's
// command, held and ramped by the base over `horizon`, would bring the body within `enough` of a
// moving disk and a stop would not let them by (a person walking into the robot from behind,
// head-on, or across: not one crossing ahead, whom a stop lets pass, its clearance no longer
// shrinking by the horizon's end), the command is chosen
// instead among a few manoeuvres by what the base would really do (core::ActuatorModel: ramps,
// cycle, latency) against every disk moved along its own velocity: the one whose body keeps the
// most clearance (up to `enough`) while none keeps half of `enough`; else, among those that keep
// half, the one whose offset point ends nearest where the target will be, each centimetre of
// clearance short of `enough` counted as kShortfallWeight centimetres farther.
//
// Why: the filter's barrier rows are instantaneous. A person closing faster than v_bar makes a
// row infeasible, and the least-slack answer to it is to flee along the person's own line at
// v_bar (the person catches up anyway); stepping aside needs a turn first, which no row rewards
// while the robot faces along the person's path. Manoeuvres (candidates): constant (v, w) on a
// grid of the diamond, turn-then-drive (w = +-w_bar in place for 0.25 to 2.5 s, then +-v_bar or
// +-v_bar / 2 straight) and turn-drive-stop (a step aside that then waits: in a corridor, a
// drive that never stops meets the wall, and clearance alone preferred backing away down the
// corridor ahead of the person); the manoeuvre's current command is what is sent, and it is kept
// while it stays clear (YieldInput::committed). Static disks count in the clearance too, so
// stepping aside does not step into a wall.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/robot/actuator_limits.h"
#include "amigobot_tracking/core/robot/actuator_model.h"
#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

// A manoeuvre: `first` for first_duration [s], then `then` for then_duration [s] (forever by
// default), then a stop: a step aside that waits beside a person's path.
struct YieldManoeuvre {
  Twist2 first;
  double first_duration = 0.0;
  Twist2 then;
  double then_duration = std::numeric_limits<double>::infinity();
  double held = 0.0;  // [s] since it was chosen

  // The command `t` [s] from now.
  Twist2 commandAt(double t) const;
  // Moves the manoeuvre's clock on by h [s] (what remains of each phase, and `held`).
  void advance(double h);
};

struct YieldInput {
  Pose2 pose;
  Twist2 previous;      // the last command sent
  // The base as it moves now: the law's own actuator model fed with the commands it sent (its
  // ramps and the commands still in the firmware's latency). Null: taken as settled at `previous`.
  const ActuatorModel* base = nullptr;
  Twist2 filtered;      // the safety filter's command
  Eigen::Vector2d target = Eigen::Vector2d::Zero();           // p_d now
  Eigen::Vector2d target_velocity = Eigen::Vector2d::Zero();  // its velocity (held over the horizon)
  double offset = 0.3;  // r [m]
  double radius = 0.18; // [m] the body's radius as the law holds it (R + body_margin)
  double horizon = 3.0; // [s] how far ahead the manoeuvres are judged (> 0)
  double enough = 0.05; // [m] a clearance this large counts as safe: ties beyond it
  ActuatorLimits limits;
  double half_track = 0.0;  // [m] 0: the AmigoBot's
  // The manoeuvre chosen at the last step, advanced to now (first_duration less the time since,
  // held more): kept, without a search, while it still keeps the body clear (predicted clearance
  // >= 0) and for at most 3 s, even where another would keep more, so the robot does not swing
  // from one side of a person to the other as the choice is made afresh (both sides are often
  // nearly as good: kept only within 3 cm of the best, 19 of 50 head-on runs touched the person;
  // kept while clear for up to 3 s, 5).
  std::optional<YieldManoeuvre> committed;
};

struct YieldResult {
  bool acted = false;                // the filter's command was replaced
  Twist2 u;                          // the command to send (= filtered when !acted)
  YieldManoeuvre manoeuvre;          // the one chosen (when acted): commit to it
  double filtered_clearance = 0.0;   // [m] the least predicted body clearance of `filtered`
  double stopped_clearance = 0.0;    // [m] ... of a stop (judged only when `filtered` is short of enough)
  double chosen_clearance = 0.0;     // [m] ... of u
  int candidates = 0;
};

// True when a disk moves (|v_j| > 0): only then can the look-ahead act.
bool anyMoving(const std::vector<Disk>& obstacles);

YieldResult yieldToMovingDisks(const YieldInput& in, const DiamondSet& diamond, const std::vector<Disk>& obstacles);

}  // namespace core
}  // namespace amigobot_tracking
