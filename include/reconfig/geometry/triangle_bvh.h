#pragma once
/// @file
/// A static axis-aligned bounding-box tree over the triangles of one posed mesh.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <limits>
#include <vector>

#include "reconfig/geometry/triangle_corners.h"

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
  /// The same, with each triangle's corners (read from the tree's leaf-ordered copy).
  void for_each_overlapping(const Eigen::AlignedBox3d& box,
                            const std::function<void(int f, const TriangleCorners& corners)>& visit) const;

  /// Calls `visit(f, g)` for every triangle f of this tree and g of `other` whose boxes
  /// overlap (closed boxes). Each pair is visited once.
  void for_each_overlapping_pair(const TriangleBvh& other,
                                 const std::function<void(int f, int g)>& visit) const;

  /// Calls `visit(f, g)` for every triangle f of this tree and g of `other` whose boxes
  /// may overlap once `other` is placed by `other_to_this` (a rigid map from `other`'s frame to
  /// this tree's): nodes of `other` are bounded by the box around their moved box, triangles by
  /// the box of their moved corners. Each pair is visited at most once.
  void for_each_overlapping_pair(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                 const std::function<void(int f, int g)>& visit) const;

  /// Two triangles whose boxes may overlap, with their corners in this tree's frame (`g`'s
  /// moved by the query's map: `other_to_this * corner`, each corner mapped once per query).
  /// The references are valid during the call only.
  struct PlacedPair {
    int f, g;
    int f_position, g_position;  ///< of f and g in their trees' `leaf_order()`
    const TriangleCorners& f_corners;
    const TriangleCorners& g_corners;
  };
  /// The pairs of the placed `for_each_overlapping_pair`, with their corners: callers that test
  /// the triangles need not look them up (or move `other`'s) again.
  void for_each_overlapping_pair(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                 const std::function<void(const PlacedPair& pair)>& visit) const;

  /// As the placed `for_each_overlapping_pair`, with `other`'s boxes grown by `distance` ≥ 0 on
  /// every side: every pair of triangles closer than `distance` to each other is visited.
  void for_each_pair_within(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this, double distance,
                            const std::function<void(int f, int g)>& visit) const;
  /// The pairs of `for_each_pair_within`, with their corners (as `PlacedPair` above).
  void for_each_pair_within(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this, double distance,
                            const std::function<void(const PlacedPair& pair)>& visit) const;

  /// The nearest point of the mesh to a query point.
  struct Nearest {
    int triangle = -1;  ///< -1 for an empty mesh
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double squared_distance = 0;
  };
  /// The triangle nearest to `q` and its nearest point (ties: the first found). Searches at
  /// most within `max_distance` (returns triangle −1 when nothing is that close).
  Nearest nearest(const Eigen::Vector3d& q, double max_distance = std::numeric_limits<double>::infinity()) const;

  /// The triangles in the order the leaves hold them (a permutation of 0..#F−1): data kept per
  /// triangle in this order is read with few cache misses by pair queries (`PlacedPair`).
  const std::vector<int>& leaf_order() const { return order_; }
  /// The corners of triangle leaf_order()[k], by k: the very doubles the pair and box queries
  /// hand to their callers.
  const std::vector<TriangleCorners>& leaf_corners() const { return ordered_corners_; }

  const Eigen::MatrixX3d& vertices() const { return V_; }
  const Eigen::MatrixX3i& faces() const { return F_; }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int left = -1, right = -1;  ///< children, or -1 for a leaf
    int begin = 0, end = 0;     ///< leaf: range in order_
  };
  /// The box query: `visit(k)` for the position k in `order_` of every triangle whose box
  /// overlaps `box`.
  template <class Visit>
  void visit_overlapping(const Eigen::AlignedBox3d& box, const Visit& visit) const;

  /// The pair traversal of every pair query: `other_node_box(node)` gives the box of a node of
  /// `other` in this tree's frame, `other_leaf_boxes(node)` the boxes of its triangles there (a
  /// pointer to node.end − node.begin boxes, in `other.order_`'s order, valid until the
  /// traversal ends); `visit(k, l)` gets the positions in `order_` and `other.order_`.
  template <class OtherNodeBox, class OtherLeafBoxes, class Visit>
  void visit_overlapping_pairs(const TriangleBvh& other, const OtherNodeBox& other_node_box,
                               const OtherLeafBoxes& other_leaf_boxes, const Visit& visit) const;

  /// The pairs of two leaves' triangles whose boxes overlap (`b_box`: leaf b's box in this
  /// frame; `other_leaf_boxes` and `visit` as above).
  template <class OtherLeafBoxes, class Visit>
  void visit_leaf_pair(const Node& a, const Eigen::AlignedBox3d& b_box, const Node& b,
                       const OtherLeafBoxes& other_leaf_boxes, const Visit& visit) const;

  /// The placed pair traversal: `visit(k, l, moved_corners)` with the corners of
  /// other.order_[l] moved into this frame.
  template <class Visit>
  void visit_placed_pairs(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this, double distance,
                          const Visit& visit) const;

  Eigen::MatrixX3d V_;
  Eigen::MatrixX3i F_;
  std::vector<Node> nodes_;
  std::vector<int> order_;  ///< triangle indices, grouped by leaf
  std::vector<Eigen::AlignedBox3d> ordered_boxes_;  ///< box of triangle order_[k], by k
  std::vector<TriangleCorners> ordered_corners_;    ///< corners of triangle order_[k], by k
};

}  // namespace reconfig::geometry
