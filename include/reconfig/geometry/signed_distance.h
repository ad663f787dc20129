#pragma once
/// @file
/// Signed distance to a closed triangle mesh, fast (a triangle tree and pseudonormals).

#include <Eigen/Core>

#include <array>
#include <limits>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/geometry/triangle_bvh.h"

namespace reconfig::geometry {

/// The signed distance to a closed, outward-oriented mesh: negative inside. The sign comes from
/// the angle-weighted pseudonormal of the nearest feature (Bærentzen & Aanæs 2005), which is
/// exact for closed manifold meshes; `point_in_solid` (winding numbers) is the slow reference.
/// Immutable once built; queries are const and thread-safe.
class MeshSignedDistance {
 public:
  /// @param mesh  a closed, outward-oriented mesh (#V×3, #F×3); copied
  explicit MeshSignedDistance(const Mesh& mesh);

  struct Query {
    double distance = 0;  ///< signed: < 0 inside, > 0 outside, 0 on the surface
    Eigen::Vector3d nearest = Eigen::Vector3d::Zero();  ///< nearest surface point
    int triangle = -1;                                   ///< the triangle it lies on
  };
  /// Signed distance at `q`. A point farther than `max_distance` from the surface gets
  /// triangle −1 and distance 0 (its side is not computed).
  Query query(const Eigen::Vector3d& q, double max_distance = std::numeric_limits<double>::infinity()) const;

  const TriangleBvh& tree() const { return tree_; }

 private:
  /// The pseudonormal of the feature of triangle f nearest to q.
  Eigen::Vector3d pseudonormal(int f, const Eigen::Vector3d& q) const;

  TriangleBvh tree_;
  std::vector<Eigen::Vector3d> face_normals_;    ///< unit (zero for degenerate faces)
  std::vector<Eigen::Vector3d> vertex_normals_;  ///< angle-weighted sums
  std::vector<std::array<Eigen::Vector3d, 3>> edge_normals_;  ///< per face, edges 01, 12, 20
};

}  // namespace reconfig::geometry
