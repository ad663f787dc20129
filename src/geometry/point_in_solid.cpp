#include "reconfig/geometry/point_in_solid.h"

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <numbers>

namespace reconfig::geometry {
namespace {

constexpr int kParallelFaces = 20000;  ///< below this many faces the sum runs serially
constexpr int kGrain = 4096;           ///< fixed blocks: the parallel sum is deterministic

/// Signed solid angle of triangle (a, b, c) seen from the origin, divided by 4π
/// (Van Oosterom & Strackee 1983): tan(Ω/2) = det[a b c] / (|a||b||c| + (a·b)|c| + (b·c)|a| + (c·a)|b|).
double solid_angle_fraction(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double det = a.dot(b.cross(c));
  const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return 2.0 * std::atan2(det, den) / (4.0 * std::numbers::pi);
}

double winding_range(const Mesh& mesh, const Eigen::Vector3d& q, int begin, int end) {
  double sum = 0.0;
  for (int f = begin; f < end; ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)).transpose() - q;
    const Eigen::Vector3d b = mesh.V.row(mesh.F(f, 1)).transpose() - q;
    const Eigen::Vector3d c = mesh.V.row(mesh.F(f, 2)).transpose() - q;
    sum += solid_angle_fraction(a, b, c);
  }
  return sum;
}

}  // namespace

double winding_number(const Mesh& mesh, const Eigen::Vector3d& q) {
  const int n = mesh.face_count();
  if (n < kParallelFaces) return winding_range(mesh, q, 0, n);
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<int>(0, n, kGrain), 0.0,
      [&](const tbb::blocked_range<int>& range, double sum) {
        return sum + winding_range(mesh, q, range.begin(), range.end());
      },
      [](double x, double y) { return x + y; });
}

bool point_in_solid(const Mesh& mesh, const Eigen::Vector3d& q) { return std::abs(winding_number(mesh, q)) >= 0.5; }

}  // namespace reconfig::geometry
