// JSON of the run reports (metrics.json, monte_carlo.json) through nlohmann::json. Keys keep
// the order they are written in, so a report reads top-down (figures first, the scenario
// last), and strings are escaped (a file name may hold quotes or backslashes).
#pragma once

#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

#include "amigobot_tracking/sim/metrics.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace sim {

using Json = nlohmann::ordered_json;

// A report's number: 10 significant digits, as the reports always had (the scripts'
// tables do not move in the last digits); integral values as integers; non-finite values
// as null (JSON has no infinity).
Json jsonNumber(double value);
// The text of a report file: indented by two, with a final line break.
std::string dumpJson(const Json& json);
// The members `keys` of the object `from`, in that order (std::out_of_range for a missing one).
Json pick(const Json& from, std::initializer_list<const char*> keys);
// The metrics every run report shares (offline run or recorded run), so both metrics.json
// files keep one schema for plot_run.py and the tests.
Json sharedMetricsJson(const sim::RunMetrics& metrics);
// {"center": [x, y], "radius": r, "velocity": [vx, vy]}, as the plots read an obstacle.
Json obstacleJson(const core::Disk& disk, const Eigen::Vector2d& velocity);

// Every figure of a run, keyed as in metrics.json (sim_time as sim_time_s, ...).
void to_json(Json& json, const RunMetrics& metrics);

}  // namespace sim
}  // namespace amigobot_tracking
