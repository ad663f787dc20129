#include "reconfig/collision/body_tree.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "reconfig/collision/kdop.h"

namespace reconfig::collision {
namespace {

struct Builder {
  const geometry::Mesh& mesh;
  std::vector<Eigen::Vector3d> centroids;
  std::vector<int> order;
  std::vector<BodyTree::Node>& nodes;
  int depth = 0;

  /// Sets a node's center and half extents so that the box certainly contains `box` despite
  /// the rounding of (min + max)/2 and (max − min)/2.
  static void set_box(BodyTree::Node& node, const Eigen::AlignedBox3d& box) {
    node.center = box.center();
    node.half = box.sizes() / 2;
    node.half.array() += 4 * std::numeric_limits<double>::epsilon() * (node.center.array().abs() + node.half.array());
  }

  Eigen::AlignedBox3d triangle_box(int f) const {
    Eigen::AlignedBox3d box;
    for (int k = 0; k < 3; ++k) box.extend(mesh.V.row(mesh.F(f, k)).transpose());
    return box;
  }

  /// Builds the subtree over order[begin, end) into nodes[index]; returns its box.
  Eigen::AlignedBox3d build(int index, int begin, int end, int level) {
    depth = std::max(depth, level);
    if (end - begin == 1) {
      const Eigen::AlignedBox3d box = triangle_box(order[begin]);
      set_box(nodes[index], box);
      nodes[index].triangle = order[begin];
      return box;
    }
    Eigen::AlignedBox3d centroid_box;
    for (int i = begin; i < end; ++i) centroid_box.extend(centroids[order[i]]);
    int axis = 0;
    centroid_box.sizes().maxCoeff(&axis);
    const int middle = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                     [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
    const int left = static_cast<int>(nodes.size());
    nodes.resize(nodes.size() + 2);
    nodes[index].left = left;
    nodes[index].right = left + 1;
    Eigen::AlignedBox3d box = build(left, begin, middle, level + 1);
    box.extend(build(left + 1, middle, end, level + 1));
    set_box(nodes[index], box);
    return box;
  }
};

}  // namespace

BodyTree::BodyTree(const geometry::Mesh& mesh) {
  assert(mesh.face_count() > 0);
  Builder builder{mesh, {}, {}, nodes_};
  builder.centroids.resize(mesh.face_count());
  for (int f = 0; f < mesh.face_count(); ++f)
    builder.centroids[f] = (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))) / 3.0;
  builder.order.resize(mesh.face_count());
  std::iota(builder.order.begin(), builder.order.end(), 0);
  nodes_.reserve(2 * mesh.face_count());
  nodes_.resize(1);
  builder.build(kRoot, 0, mesh.face_count(), 0);
  depth_ = builder.depth;
  leaf_of_.resize(mesh.face_count());
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    if (nodes_[i].leaf()) leaf_of_[nodes_[i].triangle] = static_cast<int>(i);

  // The slack bottom up (children come after their parent): a node's extent along a diagonal
  // is that of its triangles at a leaf, else the hull of its children's, each read back from
  // its box less its slack (never less than the true extent, as the slack is rounded down).
  constexpr auto kSigns = dop_axis_signs<DopFamily::k28>();
  constexpr int kDiagonals = 10;
  diagonal_slack_.resize(nodes_.size());
  const auto box_along = [&](const Node& node, int j) {  // the box's middle and reach along diagonal j
    const auto& d = kSigns[3 + j];
    double middle = 0, reach = 0;
    for (int k = 0; k < 3; ++k) middle += d[k] * node.center[k], reach += d[k] != 0 ? node.half[k] : 0.0;
    return std::pair{middle, reach};
  };
  const auto rounded_down = [](double x) {
    const float f = static_cast<float>(std::max(0.0, x));
    return f > x ? std::nextafter(f, 0.0f) : f;
  };
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    const Node& node = nodes_[i];
    for (int j = 0; j < kDiagonals; ++j) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      if (node.leaf()) {
        const auto& d = kSigns[3 + j];
        for (int c = 0; c < 3; ++c) {
          const Eigen::Vector3d v = mesh.V.row(mesh.F(node.triangle, c));
          const double value = d[0] * v.x() + d[1] * v.y() + d[2] * v.z();
          lo = std::min(lo, value), hi = std::max(hi, value);
        }
      } else {
        for (const int child : {node.left, node.right}) {
          const auto [middle, reach] = box_along(nodes_[child], j);
          lo = std::min(lo, middle - reach + diagonal_slack_[child][kDiagonals + j]);
          hi = std::max(hi, middle + reach - diagonal_slack_[child][j]);
        }
      }
      const auto [middle, reach] = box_along(node, j);
      diagonal_slack_[i][j] = rounded_down(middle + reach - hi);
      diagonal_slack_[i][kDiagonals + j] = rounded_down(lo - (middle - reach));
    }
  }

  // Connected components by union-find over the faces' vertices.
  std::vector<int> parent(mesh.vertex_count());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int k = 1; k < 3; ++k) parent[find(mesh.F(f, k))] = find(mesh.F(f, 0));
  std::vector<bool> seen(mesh.vertex_count(), false);
  for (int f = 0; f < mesh.face_count(); ++f) {
    const int root = find(mesh.F(f, 0));
    if (!seen[root]) {
      seen[root] = true;
      component_vertices_.push_back(mesh.F(f, 0));
    }
  }
}

}  // namespace reconfig::collision
