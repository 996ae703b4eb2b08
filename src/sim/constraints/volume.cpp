#include "sim/constraints/volume.h"

#include <Eigen/Geometry>

namespace systole::sim {

double enclosed_volume(const Eigen::Matrix3Xd& x, const std::vector<Eigen::Vector3i>& triangles) {
  double six_v = 0;
  for (const auto& t : triangles) six_v += x.col(t[0]).dot(x.col(t[1]).cross(x.col(t[2])));
  return six_v / 6.0;
}

double volume_and_gradient(const Eigen::Matrix3Xd& x, const std::vector<Eigen::Vector3i>& triangles,
                           Eigen::Matrix3Xd& g) {
  g.setZero();
  double six_v = 0;
  for (const auto& t : triangles) {
    const auto p0 = x.col(t[0]), p1 = x.col(t[1]), p2 = x.col(t[2]);
    six_v += p0.dot(p1.cross(p2));
    g.col(t[0]) += p1.cross(p2);
    g.col(t[1]) += p2.cross(p0);
    g.col(t[2]) += p0.cross(p1);
  }
  g /= 6.0;
  return six_v / 6.0;
}

double solve_volume(Eigen::Matrix3Xd& x, const Eigen::VectorXd& w, const Eigen::Matrix3Xd& g, double c,
                    double alpha_tilde, double lambda) {
  double denom = 0;
  for (Eigen::Index i = 0; i < x.cols(); ++i) denom += w[i] * g.col(i).squaredNorm();
  if (denom + alpha_tilde <= 0) return 0;
  const double dlambda = (-c - alpha_tilde * lambda) / (denom + alpha_tilde);
  for (Eigen::Index i = 0; i < x.cols(); ++i) x.col(i) += w[i] * dlambda * g.col(i);
  return dlambda;
}

}  // namespace systole::sim
