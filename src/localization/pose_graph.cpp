#include "amigobot_tracking/localization/pose_graph.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace amigobot_tracking {
namespace localization {

namespace {

constexpr double kHuber = 1.0;  // [sqrt(chi^2)] beyond this a robust edge's pull stops growing

Eigen::Matrix2d rotation(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d r;
  r << c, -s, s, c;
  return r;
}

// Residual of one edge and its Jacobians with respect to the poses of `from` (A) and `to` (B).
Eigen::Vector3d residual(const core::Pose2& xi, const core::Pose2& xj, const core::Pose2& z, Eigen::Matrix3d* a,
                         Eigen::Matrix3d* b) {
  const Eigen::Matrix2d ri = rotation(xi.theta), rz = rotation(z.theta);
  const Eigen::Vector2d dt(xj.x - xi.x, xj.y - xi.y);
  Eigen::Vector3d e;
  e.head<2>() = rz.transpose() * (ri.transpose() * dt - Eigen::Vector2d(z.x, z.y));
  e(2) = core::wrapAngle(xj.theta - xi.theta - z.theta);
  if (a) {
    Eigen::Matrix2d dri;  // d(Ri^T)/d(theta_i)
    dri << -std::sin(xi.theta), std::cos(xi.theta), -std::cos(xi.theta), -std::sin(xi.theta);
    a->setZero();
    a->topLeftCorner<2, 2>() = -rz.transpose() * ri.transpose();
    a->topRightCorner<2, 1>() = rz.transpose() * dri * dt;
    (*a)(2, 2) = -1.0;
    b->setZero();
    b->topLeftCorner<2, 2>() = rz.transpose() * ri.transpose();
    (*b)(2, 2) = 1.0;
  }
  return e;
}

double huberWeight(double chi2) {
  const double chi = std::sqrt(chi2);
  return chi <= kHuber ? 1.0 : kHuber / chi;
}

}  // namespace

int PoseGraph::addNode(const core::Pose2& pose) {
  nodes_.push_back(pose);
  return static_cast<int>(nodes_.size()) - 1;
}

void PoseGraph::addEdge(const PoseGraphEdge& edge) {
  const int n = static_cast<int>(nodes_.size());
  if (edge.from < 0 || edge.to < 0 || edge.from >= n || edge.to >= n || edge.from == edge.to)
    throw std::invalid_argument("pose graph: edge " + std::to_string(edge.from) + " -> " + std::to_string(edge.to) +
                                " does not join two of the " + std::to_string(n) + " nodes");
  edges_.push_back(edge);
}

double PoseGraph::error() const {
  double sum = 0.0;
  for (const PoseGraphEdge& edge : edges_) {
    const Eigen::Vector3d e = residual(nodes_[edge.from], nodes_[edge.to], edge.measurement, nullptr, nullptr);
    const double chi2 = e.dot(edge.information * e);
    sum += edge.robust ? huberWeight(chi2) * chi2 : chi2;
  }
  return sum;
}

double PoseGraph::optimize(int iterations) {
  const int n = static_cast<int>(nodes_.size());
  if (n < 2 || edges_.empty()) return error();
  for (int iteration = 0; iteration < iterations; ++iteration) {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(edges_.size() * 36 + 3);
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(3 * n);
    for (const PoseGraphEdge& edge : edges_) {
      Eigen::Matrix3d a, b;
      const Eigen::Vector3d e = residual(nodes_[edge.from], nodes_[edge.to], edge.measurement, &a, &b);
      const double w = edge.robust ? huberWeight(e.dot(edge.information * e)) : 1.0;
      const Eigen::Matrix3d omega = w * edge.information;
      const int i = 3 * edge.from, j = 3 * edge.to;
      const Eigen::Matrix3d hii = a.transpose() * omega * a, hij = a.transpose() * omega * b, hjj = b.transpose() * omega * b;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
          triplets.emplace_back(i + r, i + c, hii(r, c));
          triplets.emplace_back(i + r, j + c, hij(r, c));
          triplets.emplace_back(j + r, i + c, hij(c, r));
          triplets.emplace_back(j + r, j + c, hjj(r, c));
        }
      }
      gradient.segment<3>(i) += a.transpose() * omega * e;
      gradient.segment<3>(j) += b.transpose() * omega * e;
    }
    for (int k = 0; k < 3; ++k) triplets.emplace_back(k, k, 1e9);  // node 0 held in place
    Eigen::SparseMatrix<double> h(3 * n, 3 * n);
    h.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(h);
    if (solver.info() != Eigen::Success) throw std::runtime_error("pose graph: the system is singular (a node without edges?)");
    const Eigen::VectorXd step = solver.solve(-gradient);
    for (int k = 0; k < n; ++k) {
      nodes_[k].x += step(3 * k);
      nodes_[k].y += step(3 * k + 1);
      nodes_[k].theta = core::wrapAngle(nodes_[k].theta + step(3 * k + 2));
    }
    if (step.lpNorm<Eigen::Infinity>() < 1e-6) break;
  }
  return error();
}

}  // namespace localization
}  // namespace amigobot_tracking
