#pragma once
/// @file
/// Picking math: rays through pixels, ray–triangle and ray–mesh intersection, projecting
/// points to pixels.

#include <Eigen/Core>
#include <optional>

#include "reconfig/view/camera.h"

namespace reconfig::view {

/// A half-line origin + s · direction, s ≥ 0 (direction unit length).
struct Ray {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;
  Eigen::Vector3d at(double s) const { return origin + s * direction; }
};

/// The ray from the eye through a point of the viewport. Pixel coordinates: x to the right,
/// y downwards, (0, 0) the top-left corner of the top-left pixel; the center of pixel (i, j)
/// is (i + 0.5, j + 0.5).
Ray ray_from_pixel(const Camera& camera, int width, int height, double x, double y);

/// Where a world point lands in the viewport (same pixel coordinates as `ray_from_pixel`)
/// and its eye-space depth (distance along the viewing direction); nullopt behind the eye.
struct Projection {
  Eigen::Vector2d pixel;
  double depth = 0;
};
std::optional<Projection> project_to_pixel(const Camera& camera, int width, int height, const Eigen::Vector3d& point);

/// Ray parameter s ≥ 0 where `ray` crosses the plane through `point` with normal `normal`, or
/// nullopt when the plane is behind it or it runs (nearly) parallel to the plane (`normal`
/// need not be unit length).
std::optional<double> ray_plane(const Ray& ray, const Eigen::Vector3d& point, const Eigen::Vector3d& normal);

/// Ray parameter s ≥ 0 where `ray` crosses triangle (a, b, c) (Möller–Trumbore, both
/// sides), or nullopt when it misses or runs parallel to the triangle.
std::optional<double> ray_triangle(const Ray& ray, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c);

/// The nearest triangle of a mesh hit by a ray.
struct MeshHit {
  int face = -1;   ///< row of F
  double s = 0;    ///< ray parameter of the hit
};

/// Nearest hit of `ray` with the mesh (V, F), or nullopt. Linear in #F (picking happens once
/// per click).
/// @param V #V×3 positions (already posed)
/// @param F #F×3 triangles
std::optional<MeshHit> ray_mesh(const Ray& ray, const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

}  // namespace reconfig::view
