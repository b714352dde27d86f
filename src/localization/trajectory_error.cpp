#include "amigobot_tracking/localization/trajectory_error.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/localization/poses.h"

namespace amigobot_tracking {
namespace localization {

namespace {

void checkLengths(const std::vector<core::Pose2>& estimate, const std::vector<core::Pose2>& reference) {
  if (estimate.empty() || estimate.size() != reference.size())
    throw std::invalid_argument("trajectory error: " + std::to_string(estimate.size()) + " estimated poses for " +
                                std::to_string(reference.size()) + " reference poses");
}

void meanAndStd(const std::vector<double>& values, double* mean, double* deviation) {
  double sum = 0.0, squares = 0.0;
  for (double v : values) sum += v;
  *mean = values.empty() ? 0.0 : sum / values.size();
  for (double v : values) squares += (v - *mean) * (v - *mean);
  *deviation = values.size() < 2 ? 0.0 : std::sqrt(squares / (values.size() - 1));
}

}  // namespace

AbsoluteError absoluteError(const std::vector<core::Pose2>& estimate, const std::vector<core::Pose2>& reference) {
  checkLengths(estimate, reference);
  const std::size_t n = estimate.size();
  Eigen::Vector2d ce = Eigen::Vector2d::Zero(), cr = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    ce += estimate[i].position();
    cr += reference[i].position();
  }
  ce /= n;
  cr /= n;
  // The rotation that best turns the centred estimate onto the centred reference.
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e = estimate[i].position() - ce, r = reference[i].position() - cr;
    sxx += e.dot(r);
    sxy += e.x() * r.y() - e.y() * r.x();
  }
  const double angle = std::atan2(sxy, sxx), c = std::cos(angle), s = std::sin(angle);
  AbsoluteError result;
  result.poses = static_cast<int>(n);
  double squares = 0.0, heading_squares = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e = estimate[i].position() - ce;
    const Eigen::Vector2d aligned(c * e.x() - s * e.y() + cr.x(), s * e.x() + c * e.y() + cr.y());
    const double d = (aligned - reference[i].position()).norm();
    squares += d * d;
    result.max = std::max(result.max, d);
    const double heading = core::wrapAngle(estimate[i].theta + angle - reference[i].theta);
    heading_squares += heading * heading;
  }
  result.rms = std::sqrt(squares / n);
  result.heading_rms = std::sqrt(heading_squares / n);
  return result;
}

RelativeError relativeError(const std::vector<core::Pose2>& estimate, const Relations& relations) {
  std::vector<double> translations, rotations;
  for (const Relation& r : relations) {
    if (r.i < 0 || r.j < 0 || r.i >= static_cast<int>(estimate.size()) || r.j >= static_cast<int>(estimate.size()))
      throw std::invalid_argument("trajectory error: relation (" + std::to_string(r.i) + ", " + std::to_string(r.j) + ") outside the trajectory");
    const core::Pose2 moved = compose(inverse(estimate[r.i]), estimate[r.j]);
    const core::Pose2 error = compose(inverse(r.motion), moved);
    translations.push_back(std::hypot(error.x, error.y));
    rotations.push_back(std::abs(core::wrapAngle(error.theta)));
  }
  RelativeError result;
  result.relations = static_cast<int>(relations.size());
  meanAndStd(translations, &result.translation_mean, &result.translation_std);
  meanAndStd(rotations, &result.rotation_mean, &result.rotation_std);
  return result;
}

Relations consecutiveRelations(const std::vector<core::Pose2>& reference) {
  Relations relations;
  for (std::size_t i = 0; i + 1 < reference.size(); ++i)
    relations.push_back({static_cast<int>(i), static_cast<int>(i + 1), compose(inverse(reference[i]), reference[i + 1])});
  return relations;
}

Relations readRelations(const std::string& path, const std::vector<double>& stamps, double tolerance) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the relations file");
  const auto find = [&](double t) {
    const auto it = std::lower_bound(stamps.begin(), stamps.end(), t - tolerance);
    return it != stamps.end() && std::abs(*it - t) <= tolerance ? static_cast<int>(it - stamps.begin()) : -1;
  };
  Relations relations;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double t1 = 0.0, t2 = 0.0, x = 0.0, y = 0.0, z = 0.0, roll = 0.0, pitch = 0.0, yaw = 0.0;
    if (!(fields >> t1 >> t2 >> x >> y >> z >> roll >> pitch >> yaw))
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected 't1 t2 x y z roll pitch yaw'");
    const int i = find(t1), j = find(t2);
    if (i >= 0 && j >= 0) relations.push_back({i, j, core::Pose2{x, y, yaw}});
  }
  return relations;
}

}  // namespace localization
}  // namespace amigobot_tracking
