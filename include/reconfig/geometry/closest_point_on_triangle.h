#pragma once
/// @file
/// The point of a triangle nearest to a query point, and the feature it lies on.

#include <Eigen/Core>

namespace reconfig::geometry {

/// Which feature of triangle (a, b, c) the nearest point lies on.
enum class TriangleFeature { kFace, kEdge01, kEdge12, kEdge20, kVertex0, kVertex1, kVertex2 };

struct TriangleClosestPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  TriangleFeature feature = TriangleFeature::kFace;
};

/// The nearest point to `q` of the closed triangle (a, b, c) (Ericson, Real-Time Collision
/// Detection §5.1.5, by Voronoi regions). A degenerate triangle gives the nearest point of the
/// segment or point it collapses to, labelled with one of its edges or vertices.
TriangleClosestPoint closest_point_on_triangle(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                               const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace reconfig::geometry
