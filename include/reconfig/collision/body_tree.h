#pragma once
/// @file
/// A static bounding-box tree over one part's triangles in its rest (body) frame.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "reconfig/geometry/mesh.h"

namespace reconfig::collision {

/// Binary tree built top-down by median split on the axis of largest extent, down to one
/// triangle per leaf (reconfigurables §5.2). A part's triangles never change shape relative to
/// the part, so the tree is built once per geometry; the spacetime bounds of a node over a
/// stretch of time are derived from its box and the part's motion (`spacetime_bvh.h`).
class BodyTree {
 public:
  struct Node {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< box center (body frame)
    Eigen::Vector3d half = Eigen::Vector3d::Zero();    ///< box half extents (≥ 0)
    int left = -1, right = -1;                          ///< children; -1 for a leaf
    int triangle = -1;                                  ///< leaf: the triangle (row of F)
    bool leaf() const { return left < 0; }
  };

  BodyTree() = default;
  /// @param mesh  rest geometry: #V×3 vertices, #F×3 triangles (at least one)
  explicit BodyTree(const geometry::Mesh& mesh);

  /// How far a node's box reaches beyond its triangles along the ten diagonal directions d of
  /// space (components in {−1, 0, 1}, at least two of them nonzero, the first +1; in the order
  /// of `dop_axis_signs<DopFamily::k28>`, after x, y and z): [i] along d_i, [10 + i] along
  /// −d_i. Rounded down, never negative. The box less its slack is the node's 26-DOP in the
  /// rest frame, which bounds a rotated node much tighter than the box alone.
  using DiagonalSlack = std::array<float, 20>;
  const DiagonalSlack& diagonal_slack(int node) const { return diagonal_slack_[node]; }

  const std::vector<Node>& nodes() const { return nodes_; }
  const Node& node(int i) const { return nodes_[i]; }
  static constexpr int kRoot = 0;
  /// Depth of the deepest leaf (root = 0).
  int depth() const { return depth_; }
  /// The number of triangles (leaves).
  int triangle_count() const { return static_cast<int>(leaf_of_.size()); }
  /// The leaf node that holds a triangle (a row of the mesh's F).
  int leaf_of(int triangle) const { return leaf_of_[triangle]; }
  /// One vertex of each connected component (faces joined by shared vertices): enough to tell
  /// whether the part lies inside another when their surfaces do not cross.
  const std::vector<int>& component_vertices() const { return component_vertices_; }

 private:
  std::vector<Node> nodes_;
  std::vector<DiagonalSlack> diagonal_slack_;
  int depth_ = 0;
  std::vector<int> component_vertices_;
  std::vector<int> leaf_of_;
};

}  // namespace reconfig::collision
