#include "reconfig/geometry/triangle_bvh.h"

#include "reconfig/geometry/closest_point_on_triangle.h"
#include "reconfig/geometry/moved_vertices.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>

namespace reconfig::geometry {
namespace {

constexpr int kLeafSize = 4;
/// The pair traversal stops at nodes of at most this many triangles and compares their
/// triangles' boxes directly: a box comparison costs less than a step down both trees.
constexpr int kPairLeafSize = 8;

/// Box of triangle f: exactly the min/max of its double coordinates (no rounding involved).
Eigen::AlignedBox3d triangle_box(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int f) {
  Eigen::AlignedBox3d box(V.row(F(f, 0)).transpose());
  box.extend(V.row(F(f, 1)).transpose());
  box.extend(V.row(F(f, 2)).transpose());
  return box;
}

}  // namespace

TriangleBvh::TriangleBvh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) : V_(V), F_(F) {
  const int n = static_cast<int>(F_.rows());
  for (int f = 0; f < n; ++f)
    for (int c = 0; c < 3; ++c)
      assert(F_(f, c) >= 0 && F_(f, c) < V_.rows() && "TriangleBvh: face index out of range");
  if (n == 0) {
    nodes_.push_back(Node{});  // root with an empty box and an empty range
    return;
  }
  std::vector<Eigen::AlignedBox3d> boxes(n);
  std::vector<Eigen::Vector3d> centers(n);
  for (int f = 0; f < n; ++f) {
    boxes[f] = triangle_box(V_, F_, f);
    centers[f] = boxes[f].center();
  }
  order_.resize(n);
  for (int f = 0; f < n; ++f) order_[f] = f;
  nodes_.reserve(2 * (n / kLeafSize + 1));

  // Top-down build with an explicit stack of (node, begin, end).
  struct Task {
    int node, begin, end;
  };
  nodes_.push_back(Node{});
  std::vector<Task> stack{{0, 0, n}};
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    Eigen::AlignedBox3d box;  // empty
    Eigen::AlignedBox3d center_box;
    for (int i = task.begin; i < task.end; ++i) {
      box.extend(boxes[order_[i]]);
      center_box.extend(centers[order_[i]]);
    }
    nodes_[task.node].box = box;
    nodes_[task.node].begin = task.begin;
    nodes_[task.node].end = task.end;
    if (task.end - task.begin <= kLeafSize) continue;
    // Median split on the axis where the triangle centers spread most (ties: lowest axis).
    int axis = 0;
    const Eigen::Vector3d extent = center_box.sizes();
    for (int d = 1; d < 3; ++d)
      if (extent[d] > extent[axis]) axis = d;
    const int mid = task.begin + (task.end - task.begin) / 2;
    std::nth_element(order_.begin() + task.begin, order_.begin() + mid, order_.begin() + task.end,
                     [&](int f, int g) {
                       if (centers[f][axis] != centers[g][axis]) return centers[f][axis] < centers[g][axis];
                       return f < g;  // deterministic with equal centers
                     });
    const int left = static_cast<int>(nodes_.size());
    nodes_.push_back(Node{});
    nodes_.push_back(Node{});
    nodes_[task.node].left = left;
    nodes_[task.node].right = left + 1;
    stack.push_back({left + 1, mid, task.end});
    stack.push_back({left, task.begin, mid});
  }
  ordered_boxes_.resize(n);
  for (int k = 0; k < n; ++k) ordered_boxes_[k] = boxes[order_[k]];
}

const Eigen::AlignedBox3d& TriangleBvh::bounds() const { return nodes_.front().box; }

void TriangleBvh::for_each_overlapping(const Eigen::AlignedBox3d& box, const std::function<void(int f)>& visit) const {
  if (nodes_.front().begin == nodes_.front().end) return;
  // Depth-first with a fixed stack: a median-split tree over n < 2^31 triangles is at most
  // 31 levels deep, and the stack holds at most one pending sibling per level.
  std::array<int, 64> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!node.box.intersects(box)) continue;
    if (node.left < 0) {
      for (int i = node.begin; i < node.end; ++i) {
        if (ordered_boxes_[i].intersects(box)) visit(order_[i]);
      }
    } else {
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
  }
}

template <class OtherNodeBox, class OtherLeafBoxes>
void TriangleBvh::visit_overlapping_pairs(const TriangleBvh& other, const OtherNodeBox& other_node_box,
                                          const OtherLeafBoxes& other_leaf_boxes,
                                          const std::function<void(int f, int g)>& visit) const {
  if (nodes_.front().begin == nodes_.front().end || other.nodes_.front().begin == other.nodes_.front().end) return;
  struct Item {
    int i, j;
    Eigen::AlignedBox3d b_box;  ///< other's node j in this frame
  };
  // Depth-first; a pair is pushed only once its boxes are known to overlap. Each step down
  // leaves at most one sibling pending, and a path steps down each median-split tree (over
  // n < 2^31 triangles, leaves of kLeafSize) at most 30 times.
  std::array<Item, 128> stack;
  int top = 0;
  const Eigen::AlignedBox3d root_box = other_node_box(other.nodes_[0]);
  if (!nodes_[0].box.intersects(root_box)) return;
  stack[top++] = {0, 0, root_box};
  static_assert(kPairLeafSize >= kLeafSize);
  while (top > 0) {
    const Item item = stack[--top];
    const Node& a = nodes_[item.i];
    const Node& b = other.nodes_[item.j];
    const bool a_leaf = a.end - a.begin <= kPairLeafSize, b_leaf = b.end - b.begin <= kPairLeafSize;
    if (a_leaf && b_leaf) {
      const Eigen::AlignedBox3d* other_boxes = nullptr;  // looked up once a triangle of a meets b's box
      for (int k = a.begin; k < a.end; ++k) {
        const Eigen::AlignedBox3d& fbox = ordered_boxes_[k];
        if (!fbox.intersects(item.b_box)) continue;
        if (other_boxes == nullptr) other_boxes = other_leaf_boxes(b);
        for (int l = b.begin; l < b.end; ++l)
          if (fbox.intersects(other_boxes[l - b.begin])) visit(order_[k], other.order_[l]);
      }
      continue;
    }
    // Descend the larger (by volume-free measure: diagonal) of two inner nodes, or the inner one.
    const bool split_a =
        b_leaf || (!a_leaf && a.box.diagonal().squaredNorm() >= item.b_box.diagonal().squaredNorm());
    assert(top + 2 <= static_cast<int>(stack.size()));
    if (split_a) {
      if (nodes_[a.right].box.intersects(item.b_box)) stack[top++] = {a.right, item.j, item.b_box};
      if (nodes_[a.left].box.intersects(item.b_box)) stack[top++] = {a.left, item.j, item.b_box};
    } else {
      const Eigen::AlignedBox3d right = other_node_box(other.nodes_[b.right]);
      if (a.box.intersects(right)) stack[top++] = {item.i, b.right, right};
      const Eigen::AlignedBox3d left = other_node_box(other.nodes_[b.left]);
      if (a.box.intersects(left)) stack[top++] = {item.i, b.left, left};
    }
  }
}

void TriangleBvh::for_each_overlapping_pair(const TriangleBvh& other,
                                            const std::function<void(int f, int g)>& visit) const {
  visit_overlapping_pairs(
      other, [](const Node& node) { return node.box; },
      [&](const Node& leaf) { return other.ordered_boxes_.data() + leaf.begin; }, visit);
}

void TriangleBvh::for_each_overlapping_pair(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                            const std::function<void(int f, int g)>& visit) const {
  for_each_pair_within(other, other_to_this, 0.0, visit);
}

void TriangleBvh::for_each_pair_within(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                       double distance, const std::function<void(int f, int g)>& visit) const {
  // Each vertex of `other` is moved once, when first met.
  MovedVertices other_moved(other.V_, other_to_this);
  const Eigen::Matrix3d R = other_to_this.linear();
  const Eigen::Matrix3d R_abs = R.cwiseAbs();
  // The box around a moved box: its center moved, its half extents through |R| (exact for
  // the moved box's corners), widened by a few ulps of the coordinates for the rounding of R.
  // Each is computed once: the traversal meets a node of `other` against many of this tree's.
  const std::size_t node_count = other.nodes_.size();
  std::vector<std::uint8_t> node_known(node_count, 0);
  std::unique_ptr<Eigen::Vector3d[]> node_min(new Eigen::Vector3d[node_count]), node_max(new Eigen::Vector3d[node_count]);
  const auto node_box = [&](const Node& node) {
    const std::size_t j = &node - other.nodes_.data();
    if (!node_known[j]) {
      const Eigen::AlignedBox3d& box = node.box;
      if (box.isEmpty()) {
        node_min[j] = box.min();
        node_max[j] = box.max();
      } else {
        const Eigen::Vector3d c = other_to_this * box.center();
        const Eigen::Vector3d h = R_abs * (0.5 * box.sizes());
        const double pad = 1e-12 * (c.cwiseAbs().maxCoeff() + h.maxCoeff()) + distance;
        node_min[j] = c - h - Eigen::Vector3d::Constant(pad);
        node_max[j] = c + h + Eigen::Vector3d::Constant(pad);
      }
      node_known[j] = 1;
    }
    return Eigen::AlignedBox3d(node_min[j], node_max[j]);
  };
  // The boxes of a leaf's moved triangles, computed once, when the leaf is first met.
  std::vector<std::uint8_t> leaf_known(node_count, 0);
  // Raw storage, each box constructed when computed: an array of Eigen boxes would first set
  // every one of them empty. (Their destructors do nothing, so none is called.)
  static_assert(alignof(Eigen::AlignedBox3d) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__);
  std::unique_ptr<std::byte[]> box_storage(new std::byte[other.order_.size() * sizeof(Eigen::AlignedBox3d)]);
  auto* const triangle_boxes = reinterpret_cast<Eigen::AlignedBox3d*>(box_storage.get());
  const auto moved_leaf_boxes = [&](const Node& leaf) -> const Eigen::AlignedBox3d* {
    Eigen::AlignedBox3d* boxes = triangle_boxes + leaf.begin;
    const std::size_t j = &leaf - other.nodes_.data();
    if (leaf_known[j]) return boxes;
    for (int k = leaf.begin; k < leaf.end; ++k) {
      const int g = other.order_[k];
      Eigen::AlignedBox3d* box = new (boxes + (k - leaf.begin)) Eigen::AlignedBox3d(other_moved[other.F_(g, 0)]);
      box->extend(other_moved[other.F_(g, 1)]);
      box->extend(other_moved[other.F_(g, 2)]);
      if (distance > 0) {
        box->min().array() -= distance;
        box->max().array() += distance;
      }
    }
    leaf_known[j] = 1;
    return boxes;
  };
  visit_overlapping_pairs(other, node_box, moved_leaf_boxes, visit);
}

TriangleBvh::Nearest TriangleBvh::nearest(const Eigen::Vector3d& q, double max_distance) const {
  Nearest best;
  if (nodes_.front().begin == nodes_.front().end) return best;
  double best_d2 = max_distance * max_distance;
  const auto box_d2 = [&](const Node& node) { return node.box.squaredExteriorDistance(q); };
  // Depth-first, nearer child first, pruning nodes farther than the best so far.
  std::array<std::pair<int, double>, 64> stack;
  int top = 0;
  stack[top++] = {0, box_d2(nodes_[0])};
  while (top > 0) {
    const auto [index, d2] = stack[--top];
    if (d2 > best_d2) continue;
    const Node& node = nodes_[index];
    if (node.left < 0) {
      for (int i = node.begin; i < node.end; ++i) {
        // The triangle's box is no farther than the triangle (a little slack for rounding).
        if (ordered_boxes_[i].squaredExteriorDistance(q) > best_d2 * (1 + 1e-9)) continue;
        const int f = order_[i];
        const Eigen::Vector3d p = closest_point_on_triangle(q, V_.row(F_(f, 0)).transpose(), V_.row(F_(f, 1)).transpose(),
                                                            V_.row(F_(f, 2)).transpose())
                                      .point;
        const double e2 = (p - q).squaredNorm();
        if (e2 < best_d2 || (best.triangle < 0 && e2 <= best_d2)) {
          best_d2 = e2;
          best = {f, p, e2};
        }
      }
      continue;
    }
    const double dl = box_d2(nodes_[node.left]), dr = box_d2(nodes_[node.right]);
    if (dl <= dr) {
      stack[top++] = {node.right, dr};
      stack[top++] = {node.left, dl};
    } else {
      stack[top++] = {node.left, dl};
      stack[top++] = {node.right, dr};
    }
  }
  return best;
}

}  // namespace reconfig::geometry
