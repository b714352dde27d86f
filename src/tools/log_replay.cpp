// log_replay: a CARMEN log (FLASER / ROBOTLASER1 / ODOM lines) played through the localisation
// layer offline and scored against the log's own poses (in a corrected log such as *.gfs.log,
// the reference trajectory): mapping (--method icp: MRPT's ICP-SLAM; graph: the pose graph
// that closes loops) or localisation on a map drawn from the reference poses. Mapping prints
// three figures: the online pose (published at each scan, the node's worker timed at the log's
// real rate), the final smoothed trajectory, and the map (a second pass localised on it).
// Each: the absolute trajectory error (RMS, max) and the relative error of Kuemmerle et al.
// 2009 (with --relations, their published relations file; else consecutive reference poses).
// Odometry: --odometry log, the log's ODOM lines at each scan's stamp; drifted (default), made
// from the reference poses with --drift-scale travel and --drift-heading heading drift, plus
// seeded random slip with --drift-noise (a corrected log's ODOM lines are corrected too).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "amigobot_tracking/localization/log_replay.h"

using namespace amigobot_tracking::localization;

namespace {

void printFigures(const char* what, const AbsoluteError& ate, const RelativeError& relative, const char* relations) {
  std::printf("%-48s ATE RMS %.3f m, max %.3f m, heading RMS %.2f deg; relative (%d, %s) %.3f +- %.3f m, %.2f +- %.2f deg\n", what,
              ate.rms, ate.max, ate.heading_rms * 180.0 / M_PI, relative.relations, relations, relative.translation_mean,
              relative.translation_std, relative.rotation_mean * 180.0 / M_PI, relative.rotation_std * 180.0 / M_PI);
}

void writePoses(const std::string& path, const CarmenLog& log, const ReplayResult& r) {
  std::ofstream out(path);
  out << "# stamp ref_x ref_y ref_yaw online_x online_y online_yaw smoothed_x smoothed_y smoothed_yaw\n";
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const auto& online = r.online.empty() ? r.estimate[i] : r.online[i];
    out << log.scans[i].scan.stamp << ' ' << r.reference[i].x << ' ' << r.reference[i].y << ' ' << r.reference[i].theta << ' '
        << online.x << ' ' << online.y << ' ' << online.theta << ' ' << r.estimate[i].x << ' ' << r.estimate[i].y << ' '
        << r.estimate[i].theta << '\n';
  }
  if (!out) throw std::runtime_error(path + ": cannot write the poses");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Replays a CARMEN log through the localisation layer (mapping or localisation) and prints "
               "ATE and relative error against the log's reference poses");
  std::string log_path, mode = "mapping", method = "graph", relations_path, save_map, poses_path, odometry = "drifted";
  double range_max = 20.0, max_ate = -1.0;
  int scans = 0;
  OdometryDrift drift;
  double drift_heading_deg = drift.heading_per_metre * 180.0 / M_PI;
  app.add_option("log", log_path, "CARMEN log (e.g. test/data/real/intel.gfs.log)")->required();
  app.add_option("--mode", mode, "mapping or localization (on a map drawn from the reference poses)")
      ->capture_default_str()
      ->check(CLI::IsMember({"mapping", "localization"}));
  app.add_option("--method", method, "mapping: icp (MRPT ICP-SLAM) or graph (pose graph, closes loops)")
      ->capture_default_str()
      ->check(CLI::IsMember({"icp", "graph"}));
  app.add_option("--odometry", odometry, "log (the ODOM lines) or drifted (the reference, +2 % travel, 1.5 deg/m turn)")
      ->capture_default_str()
      ->check(CLI::IsMember({"log", "drifted"}));
  app.add_option("--drift-scale", drift.scale, "drifted odometry: travel scale")->capture_default_str()->check(CLI::Range(0.5, 1.5));
  app.add_option("--drift-heading", drift_heading_deg, "[deg/m] drifted odometry: heading drift per metre")
      ->capture_default_str()
      ->check(CLI::Range(-20.0, 20.0));
  app.add_option("--drift-noise", drift.noise, "drifted odometry: per-step slip, std of travel fraction and of rad/m")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.5));
  app.add_option("--seed", drift.seed, "drifted odometry: seed of the slip")->capture_default_str();
  app.add_option("--range-max", range_max, "[m] farther echoes are ignored")->capture_default_str()->check(CLI::Range(0.5, 80.0));
  app.add_option("--relations", relations_path, "relations file of Kuemmerle et al. (t1 t2 x y z roll pitch yaw)");
  app.add_option("--scans", scans, "replay only the first N scans (0: all)")->check(CLI::NonNegativeNumber);
  app.add_option("--save-map", save_map, "write the map (built or drawn) to this YAML (+ PGM beside it)");
  app.add_option("--poses", poses_path, "write per scan: stamp, reference, online and smoothed (or localised) x y yaw");
  app.add_option("--max-ate", max_ate, "[m] exit 3 when the ATE RMS (mapping: of the online pose) is above this");
  app.footer("Exit 0: replayed (and within --max-ate); 1: the log, relations or map cannot be used; 2: bad arguments; "
             "3: ATE RMS above --max-ate.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    CarmenLog log = readCarmenLog(log_path);
    if (scans > 0 && scans < static_cast<int>(log.scans.size())) log.scans.resize(static_cast<std::size_t>(scans));
    drift.heading_per_metre = drift_heading_deg * M_PI / 180.0;
    if (odometry == "drifted") driftOdometry(&log, drift);
    LocalizationConfig config;
    config.mapping_method = method;
    config.range_max = range_max;
    Relations relations;
    if (!relations_path.empty()) {
      std::vector<double> stamps;
      for (const LogScan& s : log.scans) stamps.push_back(s.scan.stamp);
      relations = readRelations(relations_path, stamps);
      if (relations.empty()) throw std::runtime_error(relations_path + ": no relation matches the log's timestamps");
    }
    ReplayResult r, on_map;
    if (mode == "mapping") {
      r = replayMapping(log, config, relations);
      on_map = replayLocalization(log, config, r.map, relations);
    } else {
      r = replayLocalization(log, config, referenceMap(log, config.resolution, range_max), relations);
    }
    if (!poses_path.empty()) writePoses(poses_path, log, r);
    if (!save_map.empty()) saveMap(save_map, mode == "mapping" ? r.map : referenceMap(log, config.resolution, range_max));
    std::printf("log %s: %zu scans, %d ODOM lines; odometry %s", log_path.c_str(), log.scans.size(), log.odom_lines, odometry.c_str());
    if (odometry == "drifted")
      std::printf(" (travel x%.3f, %.2f deg/m, slip %.3f seed %u)", drift.scale, drift_heading_deg, drift.noise, drift.seed);
    std::printf(" alone: ATE RMS %.3f m, max %.3f m\n", r.odometry_ate.rms, r.odometry_ate.max);
    std::printf("mode %s%s: %.2f s CPU (%.1f ms per scan, slowest %.0f ms), %d loop closures\n", mode.c_str(),
                mode == "mapping" ? (" (" + method + ")").c_str() : "", r.seconds, 1e3 * r.seconds / log.scans.size(),
                1e3 * r.max_update, r.loop_closures);
    const char* relations_kind = relations_path.empty() ? "consecutive reference poses" : "relations file";
    if (mode == "mapping") {
      std::printf("scans dropped by the node's worker at the log's real rate: %d\n", r.dropped);
      printFigures("online pose (published at each scan)", r.online_ate, r.online_relative, relations_kind);
      printFigures("smoothed trajectory (optimised at the end)", r.ate, r.relative, relations_kind);
      printFigures("map quality (second pass localised on the map)", on_map.ate, on_map.relative, relations_kind);
    } else {
      printFigures("localisation on the reference map", r.ate, r.relative, relations_kind);
    }
    const double checked = mode == "mapping" ? r.online_ate.rms : r.ate.rms;
    if (max_ate >= 0.0 && !(checked <= max_ate)) {
      std::fprintf(stderr, "log_replay: ATE RMS %.3f m above --max-ate %.3f m\n", checked, max_ate);
      return 3;
    }
  } catch (const std::exception& e) {
    std::cerr << "log_replay: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
