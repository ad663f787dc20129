#pragma once
/// @file
/// A static axis-aligned bounding-box tree over the triangles of one posed mesh.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <vector>

namespace reconfig::geometry {

/// Bounding-box hierarchy over triangles, built top-down by median split on the axis of
/// largest extent. Immutable once built; queries are const and thread-safe.
class TriangleBvh {
 public:
  /// @param V #V×3 vertex positions (copied)
  /// @param F #F×3 triangles
  TriangleBvh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

  /// Box of every triangle (empty box for an empty mesh).
  const Eigen::AlignedBox3d& bounds() const;

  /// Calls `visit(f)` for every triangle f whose box overlaps `box` (closed boxes).
  void for_each_overlapping(const Eigen::AlignedBox3d& box, const std::function<void(int f)>& visit) const;

  /// Calls `visit(f, g)` for every triangle f of this tree and g of `other` whose boxes
  /// overlap (closed boxes). Each pair is visited once.
  void for_each_overlapping_pair(const TriangleBvh& other,
                                 const std::function<void(int f, int g)>& visit) const;

  const Eigen::MatrixX3d& vertices() const { return V_; }
  const Eigen::MatrixX3i& faces() const { return F_; }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int left = -1, right = -1;  ///< children, or -1 for a leaf
    int begin = 0, end = 0;     ///< leaf: range in order_
  };
  Eigen::MatrixX3d V_;
  Eigen::MatrixX3i F_;
  std::vector<Node> nodes_;
  std::vector<int> order_;  ///< triangle indices, grouped by leaf
};

}  // namespace reconfig::geometry
