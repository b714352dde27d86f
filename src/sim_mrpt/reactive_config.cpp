// The INI text of MRPT's reactive navigator for the project's robot and limits.
#include <cmath>
#include <sstream>

#include "amigobot_tracking/sim_mrpt/reactive_law.h"

namespace amigobot_tracking {
namespace sim_mrpt {
namespace {

// A PTG of the differential drive, with the diamond's corners as its speed limits.
void writePtg(std::ostringstream& ini, int index, const char* type, const core::ControllerConfig& c,
              const ReactiveLawOptions& o, const char* extra, double priority) {
  ini << "PTG" << index << "_Type = " << type << "\n"
      << "PTG" << index << "_resolution = " << o.ptg_resolution << "\n"
      << "PTG" << index << "_refDistance = " << o.ref_distance << "\n"
      << "PTG" << index << "_num_paths = " << o.ptg_paths << "\n"
      << "PTG" << index << "_v_max_mps = " << c.v_max << "\n"
      << "PTG" << index << "_w_max_dps = " << c.w_max * 180.0 / M_PI << "\n"
      << extra << "PTG" << index << "_score_priority = " << priority << "\n";
}

}  // namespace

std::string reactiveConfigText(const core::ControllerConfig& c, const ReactiveLawOptions& o) {
  std::ostringstream ini;
  ini.precision(10);
  ini << "[CAbstractNavigator]\n"
      << "dist_to_target_for_sending_event = 0\n"
      << "alarm_seems_not_approaching_target_timeout = 1e9\n"  // re-targeted every period: never give up
      << "dist_check_target_is_blocked = 0\n"
      << "hysteresis_check_target_is_blocked = 3\n"
      << "enable_time_profiler = false\n"
      << "[CWaypointsNavigator]\n"
      << "max_distance_to_allow_skip_waypoint = -1\n"
      << "min_timesteps_confirm_skip_waypoints = 1\n"
      << "waypoint_angle_tolerance = 5\n"
      << "multitarget_look_ahead = 0\n"
      << "[CAbstractPTGBasedReactive]\n"
      << "robotMax_V_mps = " << c.v_max << "\n"
      << "robotMax_W_degps = " << c.w_max * 180.0 / M_PI << "\n"
      << "holonomic_method = " << o.holonomic << "\n"
      << "motion_decider_method = CMultiObjMotionOpt_Scalarization\n"
      << "ref_distance = " << o.ref_distance << "\n"
      << "speedfilter_tau = 0\n"
      // Normalised by ref_distance: 0.04-0.2 m of free path before the speed ramps to zero (MRPT's
      // example 0.05-0.15 of 10 m stops the robot for good 0.3 m from the ring's small disks).
      << "secure_distance_start = 0.01\n"
      << "secure_distance_end = 0.05\n"
      << "use_delays_model = false\n"
      << "max_distance_predicted_actual_path = 0.15\n"
      << "min_normalized_free_space_for_ptg_continuation = 0.2\n"
      << "enable_obstacle_filtering = false\n"  // an ideal simulated laser: nothing to filter
      << "evaluate_clearance = false\n"

      << "[CHolonomicND]\n"
      << "WIDE_GAP_SIZE_PERCENT = 0.25\n"
      << "MAX_SECTOR_DIST_FOR_D2_PERCENT = 0.25\n"
      << "RISK_EVALUATION_SECTORS_PERCENT = 0.1\n"
      << "RISK_EVALUATION_DISTANCE = 0.4\n"
      << "TOO_CLOSE_OBSTACLE = 0.02\n"
      << "TARGET_SLOW_APPROACHING_DISTANCE = 0.1\n"
      << "factorWeights = 1.0 0.5 2.0 0.4\n"
      << "[CHolonomicVFF]\n"
      << "TARGET_SLOW_APPROACHING_DISTANCE = 0.1\n"
      << "TARGET_ATTRACTIVE_FORCE = 20\n"
      << "[CHolonomicFullEval]\n"
      << "factorWeights = [0.25, 0.1, 1, 0.05, 0.5, 1, 1]\n"
      << "factorNormalizeOrNot = [0, 0, 0, 0, 1, 1, 0]\n"
      << "TOO_CLOSE_OBSTACLE = 0.15\n"
      << "TARGET_SLOW_APPROACHING_DISTANCE = 0.1\n"
      << "OBSTACLE_SLOW_DOWN_DISTANCE = 0.15\n"
      << "HYSTERESIS_SECTOR_COUNT = 5\n"
      << "LOG_SCORE_MATRIX = false\n"
      << "clearance_threshold_ratio = 0.1\n"
      << "gap_width_ratio_threshold = 0.2\n"
      << "PHASE_COUNT = 3\n"
      << "PHASE1_FACTORS = [6]\nPHASE1_THRESHOLD = 0.5\n"
      << "PHASE2_FACTORS = [4]\nPHASE2_THRESHOLD = 0.7\n"
      << "PHASE3_FACTORS = [0 2]\nPHASE3_THRESHOLD = 0.7\n"
      // Candidate scores (exprtk) and their scalarisation: MRPT's documented example set.
      << "[CMultiObjectiveMotionOptimizerBase]\n"
      << "score1_name = target_distance\n"
      << "score1_formula = var effective_trg_d_norm := max(0,target_d_norm-move_cur_d); "
         "if(collision_free_distance>effective_trg_d_norm, 1/(1+effective_trg_d_norm^2), 0)\n"
      << "score2_name = collision_free_distance_score\n"
      << "score2_formula = var effective_trg_d_norm := max(0,target_d_norm-move_cur_d); "
         "if (collision_free_distance>(effective_trg_d_norm+0.05), 1.0, collision_free_distance)\n"
      << "score3_name = euclidean_nearness\n"
      << "score3_formula = 1/(1+dist_eucl_min^2)\n"
      << "score4_name = hysteresis_score\n"
      << "score4_formula = hysteresis\n"
      << "score5_name = path_index_near_target\n"
      << "score5_formula = var dif:=abs(target_k-move_k); if (dif>(num_paths/2)) { dif:=num_paths-dif; }; "
         "exp(-abs(dif / (num_paths/10.0)));\n"
      << "score6_name = ptg_priority_score\n"
      << "score6_formula = ptg_priority\n"
      << "scores_to_normalize =\n"
      << "[CMultiObjMotionOpt_Scalarization]\n"
      << "scalar_score_formula = ptg_priority_score*(0.3*target_distance + 0.5*collision_free_distance_score + "
         "8.0*euclidean_nearness + 0.1*hysteresis_score + 0.2*path_index_near_target)\n"
      << "[CReactiveNavigationSystem]\n"
      << "min_obstacles_height = -1\n"
      << "max_obstacles_height = 10\n"
      << "PTG_COUNT = 3\n";
  // alpha first: its paths reach every direction, so the first candidate MRPT scores always has
  // the score variables (MRPT 2.5 compiles the score formulas from the first candidate's; a
  // target outside PTG 0's domain made every step fail with "Undefined symbol").
  writePtg(ini, 0, "CPTG_DiffDrive_alpha", c, o, "PTG0_cte_a0v_deg = 57\nPTG0_cte_a0w_deg = 57\n", 1.0);
  writePtg(ini, 1, "CPTG_DiffDrive_C", c, o, "PTG1_K = 1.0\n", 1.0);
  writePtg(ini, 2, "CPTG_DiffDrive_C", c, o, "PTG2_K = -1.0\n", 0.5);  // backwards
  // The body disk of radius R, circumscribed by a 16-gon (the diff-drive PTGs take a polygon).
  const int corners = 16;
  const double r = c.robot_radius / std::cos(M_PI / corners);
  std::ostringstream xs, ys;
  xs.precision(10);
  ys.precision(10);
  for (int k = 0; k < corners; ++k) {
    xs << (k ? " " : "") << r * std::cos(2.0 * M_PI * k / corners);
    ys << (k ? " " : "") << r * std::sin(2.0 * M_PI * k / corners);
  }
  ini << "RobotModel_shape2D_xs = " << xs.str() << "\n"
      << "RobotModel_shape2D_ys = " << ys.str() << "\n";
  return ini.str();
}

}  // namespace sim_mrpt
}  // namespace amigobot_tracking
