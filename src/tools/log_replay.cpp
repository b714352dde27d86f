// log_replay: a CARMEN log (FLASER / ROBOTLASER1 / ODOM lines) played through the localisation
// layer offline, as fast as the CPU allows, and scored against the log's own poses (in a
// corrected log such as *.gfs.log, the reference trajectory): mapping (--method icp: MRPT's
// ICP-SLAM; graph: the pose graph that closes loops) or localisation on a map drawn from the
// reference poses. Prints the absolute trajectory error (RMS, max) and the relative error of
// Kuemmerle et al. 2009 (with --relations, their published relations file; else consecutive
// reference poses). Odometry: --odometry log, the log's ODOM lines at each scan's stamp;
// drifted (default), made from the reference poses with +2 % travel and 1.5 deg/m heading drift
// (a corrected log's ODOM lines are corrected too).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "amigobot_tracking/localization/log_replay.h"

using namespace amigobot_tracking::localization;

int main(int argc, char** argv) {
  CLI::App app("Replays a CARMEN log through the localisation layer (mapping or localisation) and prints "
               "ATE and relative error against the log's reference poses");
  std::string log_path, mode = "mapping", method = "graph", relations_path, save_map, odometry = "drifted";
  double range_max = 20.0, max_ate = -1.0;
  int scans = 0;
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
  app.add_option("--range-max", range_max, "[m] farther echoes are ignored")->capture_default_str()->check(CLI::Range(0.5, 80.0));
  app.add_option("--relations", relations_path, "relations file of Kuemmerle et al. (t1 t2 x y z roll pitch yaw)");
  app.add_option("--scans", scans, "replay only the first N scans (0: all)")->check(CLI::NonNegativeNumber);
  app.add_option("--save-map", save_map, "write the map (built or drawn) to this YAML (+ PGM beside it)");
  app.add_option("--max-ate", max_ate, "[m] exit 3 when the ATE RMS is above this");
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
    if (odometry == "drifted") driftOdometry(&log, OdometryDrift());
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
    ReplayResult r;
    if (mode == "mapping") {
      r = replayMapping(log, config, relations);
    } else {
      r = replayLocalization(log, config, referenceMap(log, config.resolution, range_max), relations);
    }
    if (!save_map.empty()) saveMap(save_map, mode == "mapping" ? r.map : referenceMap(log, config.resolution, range_max));
    std::printf("log %s: %zu scans, %d ODOM lines\n", log_path.c_str(), log.scans.size(), log.odom_lines);
    std::printf("mode %s%s: %.2f s CPU (%.1f ms per scan), %d loop closures\n", mode.c_str(),
                mode == "mapping" ? (" (" + method + ")").c_str() : "", r.seconds, 1e3 * r.seconds / log.scans.size(), r.loop_closures);
    std::printf("ATE RMS %.3f m, max %.3f m, heading RMS %.2f deg (odometry alone: RMS %.3f m, max %.3f m)\n", r.ate.rms,
                r.ate.max, r.ate.heading_rms * 180.0 / M_PI, r.odometry_ate.rms, r.odometry_ate.max);
    std::printf("relative error (%d relations%s): translation %.3f +- %.3f m, rotation %.2f +- %.2f deg\n",
                r.relative.relations, relations_path.empty() ? ", consecutive reference poses" : "", r.relative.translation_mean,
                r.relative.translation_std, r.relative.rotation_mean * 180.0 / M_PI, r.relative.rotation_std * 180.0 / M_PI);
    if (max_ate >= 0.0 && !(r.ate.rms <= max_ate)) {
      std::fprintf(stderr, "log_replay: ATE RMS %.3f m above --max-ate %.3f m\n", r.ate.rms, max_ate);
      return 3;
    }
  } catch (const std::exception& e) {
    std::cerr << "log_replay: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
