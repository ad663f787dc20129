#pragma once
/// @file
/// A sweeper tool: a shape with a distance field, placed in space, with a coating (Sweepers §3.1).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>

#include "reconfig/geometry/mesh.h"
#include "reconfig/geometry/signed_distance.h"

namespace reconfig::sculpt {

/// Where a tool is: x_world = scale · rotation · x_tool + translation (a similarity, the
/// absolute transformation M^t of the paper, products of translations, rotations and uniform
/// scalings).
struct ToolPose {
  double scale = 1;                                            ///< uniform scale (> 0)
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< unit quaternion
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();       ///< where the tool's origin is

  Eigen::Vector3d to_world(const Eigen::Vector3d& x) const { return scale * (rotation * x) + translation; }
  Eigen::Vector3d to_tool(const Eigen::Vector3d& p) const {
    return rotation.conjugate() * (p - translation) / scale;
  }
};

/// The shapes a tool can have. Primitives are centered at the tool's origin.
enum class ToolShape {
  kSphere,     ///< radius `size.x()`
  kBox,        ///< half edge lengths `size`
  kCapsule,    ///< radius `size.x()` around the segment z ∈ [−size.z(), size.z()]
  kEllipsoid,  ///< semi-axes `size`
  kMesh,       ///< a baked closed mesh (its signed distance through a triangle tree)
};

/// A tool j: a distance field d_j placed by a pose, and its field φ_j = μ(d_j) with coating λ_j.
///
/// Distances are exact Euclidean distances for the sphere, box, capsule and baked mesh. For the
/// ellipsoid, d = (‖x ⊘ r‖ − 1)·min(r): closed form, zero exactly on the ellipsoid, negative
/// inside and 1-Lipschitz (so it never exceeds the Euclidean distance) — the foldover bounds
/// only need |∇d| ≤ 1, which every tool's field satisfies. The distance of a placed tool is
/// scale · d(x_tool) (the paper's det(M)^{1/3} d(M⁻¹p)).
///
/// Copies share a baked mesh's distance structure; queries are const and thread-safe.
class Tool {
 public:
  /// A sphere of `radius` (> 0) centered at `center`.
  static Tool sphere(double radius, const Eigen::Vector3d& center, double coating);
  /// An axis-aligned box of edge lengths `size` (each > 0) centered at `center`.
  static Tool box(const Eigen::Vector3d& size, const Eigen::Vector3d& center, double coating);
  /// A capsule of `radius` around a segment of `length` (≥ 0) along z, centered at `center`.
  static Tool capsule(double radius, double length, const Eigen::Vector3d& center, double coating);
  /// An axis-aligned ellipsoid of semi-axes `radii` (each > 0) centered at `center`.
  static Tool ellipsoid(const Eigen::Vector3d& radii, const Eigen::Vector3d& center, double coating);
  /// A baked tool: `mesh` (#V×3, #F×3; closed and outward-oriented, checked by the caller)
  /// with its signed distance precomputed, in place where it is (the tool's origin is the
  /// world's: pose identity).
  static Tool baked(const geometry::Mesh& mesh, double coating);

  ToolShape shape() const { return shape_; }
  double coating() const { return coating_; }
  const ToolPose& pose() const { return pose_; }
  void set_pose(const ToolPose& pose) { pose_ = pose; }

  /// Distance from world point `p` to the placed tool (< 0 inside). Beyond the coating the
  /// value is only guaranteed to be ≥ the coating (a baked tool stops searching there).
  double distance(const Eigen::Vector3d& p) const;
  /// The distance and its gradient at `p` (unit length outside the tool; zero inside, where
  /// φ = 1 does not depend on it).
  double distance(const Eigen::Vector3d& p, Eigen::Vector3d& gradient) const;
  /// φ(p) = μ(d(p)) ∈ [0, 1].
  double field(const Eigen::Vector3d& p) const;
  /// φ(p) and ∇φ(p) = μ'(d) ∇d.
  double field(const Eigen::Vector3d& p, Eigen::Vector3d& gradient) const;

  /// An axis-aligned world box containing the coating K and the inside T (every point where
  /// φ > 0): the placed shape's box widened by the coating (for the ellipsoid, the box of the
  /// ellipsoid where its field reaches λ). The "box around K" of eq. (1)–(3).
  Eigen::AlignedBox3d field_box() const;

 private:
  Tool(ToolShape shape, const Eigen::Vector3d& size, const Eigen::Vector3d& center, double coating);
  /// Distance and gradient (unit outside) in the tool's own frame.
  double local_distance(const Eigen::Vector3d& x, Eigen::Vector3d* gradient) const;

  ToolShape shape_ = ToolShape::kSphere;
  Eigen::Vector3d size_ = Eigen::Vector3d::Ones();
  double coating_ = 1;
  ToolPose pose_;
  Eigen::AlignedBox3d local_box_;  ///< the shape's box in its own frame
  std::shared_ptr<const geometry::MeshSignedDistance> baked_;
};

}  // namespace reconfig::sculpt
