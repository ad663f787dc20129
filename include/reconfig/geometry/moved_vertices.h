#pragma once
/// @file
/// A mesh's vertices under one rigid map, each mapped once, when first asked for.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <vector>

namespace reconfig::geometry {

/// `map * V.row(v)` for the vertices a query meets, computed on first use and kept: a pair
/// traversal of two trees meets each vertex of the moved mesh in many triangle pairs. The value
/// is the same expression evaluated once (bit for bit what mapping the vertex again gives).
/// Holds a reference to V. Not thread-safe: one per query.
class MovedVertices {
 public:
  /// @param V    #V×3 vertex positions (referenced, not copied)
  /// @param map  rigid map applied to them
  MovedVertices(const Eigen::MatrixX3d& V, const Eigen::Isometry3d& map)
      : V_(V), map_(map), moved_(new Eigen::Vector3d[V.rows()]), known_(V.rows(), 0) {}

  const Eigen::Vector3d& operator[](int v) {
    if (!known_[v]) {
      moved_[v] = map_ * V_.row(v).transpose();
      known_[v] = 1;
    }
    return moved_[v];
  }
  const Eigen::Isometry3d& map() const { return map_; }
  const Eigen::MatrixX3d& rest() const { return V_; }

 private:
  const Eigen::MatrixX3d& V_;
  Eigen::Isometry3d map_;
  std::unique_ptr<Eigen::Vector3d[]> moved_;
  std::vector<std::uint8_t> known_;
};

}  // namespace reconfig::geometry
