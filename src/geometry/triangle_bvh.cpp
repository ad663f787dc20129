#include "reconfig/geometry/triangle_bvh.h"

#include "reconfig/geometry/closest_point_on_triangle.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace reconfig::geometry {
namespace {

constexpr int kLeafSize = 4;
/// The pair traversal stops at nodes of at most this many triangles (of this tree, and of the
/// other) and compares their triangles' boxes directly: a box comparison costs less than a step
/// down both trees. The other's may be larger: its nodes' boxes are the looser ones (moved
/// boxes, bounded again) and cost more to compute, its triangles' boxes are exact.
constexpr int kPairLeafSize = 8;
constexpr int kOtherPairLeafSize = 32;

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
  ordered_corners_.resize(n);
  for (int k = 0; k < n; ++k) {
    const int f = order_[k];
    ordered_boxes_[k] = boxes[f];
    ordered_corners_[k] = {V_.row(F_(f, 0)).transpose(), V_.row(F_(f, 1)).transpose(), V_.row(F_(f, 2)).transpose()};
  }
}

const Eigen::AlignedBox3d& TriangleBvh::bounds() const { return nodes_.front().box; }

template <class Visit>
void TriangleBvh::visit_overlapping(const Eigen::AlignedBox3d& box, const Visit& visit) const {
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
      for (int k = node.begin; k < node.end; ++k) {
        if (ordered_boxes_[k].intersects(box)) visit(k);
      }
    } else {
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
  }
}

void TriangleBvh::for_each_overlapping(const Eigen::AlignedBox3d& box, const std::function<void(int f)>& visit) const {
  visit_overlapping(box, [&](int k) { visit(order_[k]); });
}

void TriangleBvh::for_each_overlapping(const Eigen::AlignedBox3d& box,
                                       const std::function<void(int f, const TriangleCorners& corners)>& visit) const {
  visit_overlapping(box, [&](int k) { visit(order_[k], ordered_corners_[k]); });
}

template <class OtherLeafBoxes, class Visit>
void TriangleBvh::visit_leaf_pair(const Node& a, const Eigen::AlignedBox3d& b_box, const Node& b,
                                  const OtherLeafBoxes& other_leaf_boxes, const Visit& visit) const {
  // The triangles of each leaf that meet the other leaf's box: only those can meet each other
  // (a triangle's box lies in its node's box), and each side is tested once instead of per pair.
  std::array<int, kPairLeafSize> near_a;
  std::array<int, kOtherPairLeafSize> near_b;
  int count_a = 0, count_b = 0;
  for (int k = a.begin; k < a.end; ++k)
    if (ordered_boxes_[k].intersects(b_box)) near_a[count_a++] = k;
  if (count_a == 0) return;
  const Eigen::AlignedBox3d* other_boxes = other_leaf_boxes(b);
  for (int l = b.begin; l < b.end; ++l)
    if (other_boxes[l - b.begin].intersects(a.box)) near_b[count_b++] = l;
  for (int i = 0; i < count_a; ++i) {
    const Eigen::AlignedBox3d& fbox = ordered_boxes_[near_a[i]];
    for (int j = 0; j < count_b; ++j)
      if (fbox.intersects(other_boxes[near_b[j] - b.begin])) visit(near_a[i], near_b[j]);
  }
}

template <class OtherNodeBox, class OtherLeafBoxes, class Visit>
void TriangleBvh::visit_overlapping_pairs(const TriangleBvh& other, const OtherNodeBox& other_node_box,
                                          const OtherLeafBoxes& other_leaf_boxes, const Visit& visit) const {
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
  static_assert(kPairLeafSize >= kLeafSize && kOtherPairLeafSize >= kLeafSize);
  while (top > 0) {
    const Item item = stack[--top];
    const Node& a = nodes_[item.i];
    const Node& b = other.nodes_[item.j];
    const bool a_leaf = a.end - a.begin <= kPairLeafSize, b_leaf = b.end - b.begin <= kOtherPairLeafSize;
    if (a_leaf && b_leaf) {
      visit_leaf_pair(a, item.b_box, b, other_leaf_boxes, visit);
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
      [&](const Node& leaf) { return other.ordered_boxes_.data() + leaf.begin; },
      [&](int k, int l) { visit(order_[k], other.order_[l]); });
}

template <class Visit>
void TriangleBvh::visit_placed_pairs(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                     double distance, const Visit& visit) const {
  const Eigen::Matrix3d R = other_to_this.linear();
  const Eigen::Matrix3d R_abs = R.cwiseAbs();
  // The box around a moved box: its center moved, its half extents through |R| (exact for
  // the moved box's corners), widened by a few ulps of the coordinates for the rounding of R.
  // Each is computed once: the traversal meets a node of `other` against many of this tree's.
  // Raw storage below, each element constructed when computed: arrays of Eigen objects would
  // first initialize every one of them. (Their destructors do nothing, so none is called.)
  static_assert(alignof(Eigen::AlignedBox3d) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__);
  static_assert(alignof(TriangleCorners) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__);
  static_assert(std::is_trivially_destructible_v<TriangleCorners>);  // AlignedBox3d's destructor is empty
  const std::size_t node_count = other.nodes_.size();
  std::vector<std::uint8_t> node_known(node_count, 0);
  std::unique_ptr<std::byte[]> node_storage(new std::byte[node_count * sizeof(Eigen::AlignedBox3d)]);
  auto* const node_boxes = reinterpret_cast<Eigen::AlignedBox3d*>(node_storage.get());
  const auto node_box = [&](const Node& node) -> const Eigen::AlignedBox3d& {
    const std::size_t j = &node - other.nodes_.data();
    if (!node_known[j]) {
      const Eigen::AlignedBox3d& box = node.box;
      if (box.isEmpty()) {
        new (node_boxes + j) Eigen::AlignedBox3d(box);
      } else {
        const Eigen::Vector3d c = other_to_this * box.center();
        const Eigen::Vector3d h = R_abs * (0.5 * box.sizes());
        const double pad = 1e-12 * (c.cwiseAbs().maxCoeff() + h.maxCoeff()) + distance;
        new (node_boxes + j) Eigen::AlignedBox3d(c - h - Eigen::Vector3d::Constant(pad), c + h + Eigen::Vector3d::Constant(pad));
      }
      node_known[j] = 1;
    }
    return node_boxes[j];
  };
  // The moved corners of a leaf's triangles and their boxes, computed once, when the leaf is
  // first met.
  std::vector<std::uint8_t> leaf_known(node_count, 0);
  const std::size_t n = other.order_.size();
  std::unique_ptr<std::byte[]> box_storage(new std::byte[n * sizeof(Eigen::AlignedBox3d)]);
  std::unique_ptr<std::byte[]> corner_storage(new std::byte[n * sizeof(TriangleCorners)]);
  auto* const triangle_boxes = reinterpret_cast<Eigen::AlignedBox3d*>(box_storage.get());
  auto* const moved_corners = reinterpret_cast<TriangleCorners*>(corner_storage.get());
  const auto moved_leaf_boxes = [&](const Node& leaf) -> const Eigen::AlignedBox3d* {
    const std::size_t j = &leaf - other.nodes_.data();
    if (leaf_known[j]) return triangle_boxes + leaf.begin;
    for (int k = leaf.begin; k < leaf.end; ++k) {
      const TriangleCorners& rest = other.ordered_corners_[k];
      TriangleCorners* moved = new (moved_corners + k)
          TriangleCorners{other_to_this * rest[0], other_to_this * rest[1], other_to_this * rest[2]};
      Eigen::AlignedBox3d* box = new (triangle_boxes + k) Eigen::AlignedBox3d((*moved)[0]);
      box->extend((*moved)[1]);
      box->extend((*moved)[2]);
      if (distance > 0) {
        box->min().array() -= distance;
        box->max().array() += distance;
      }
    }
    leaf_known[j] = 1;
    return triangle_boxes + leaf.begin;
  };
  visit_overlapping_pairs(other, node_box, moved_leaf_boxes, [&](int k, int l) { visit(k, l, moved_corners[l]); });
}

void TriangleBvh::for_each_overlapping_pair(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                            const std::function<void(int f, int g)>& visit) const {
  for_each_pair_within(other, other_to_this, 0.0, visit);
}

void TriangleBvh::for_each_overlapping_pair(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                            const std::function<void(const PlacedPair& pair)>& visit) const {
  for_each_pair_within(other, other_to_this, 0.0, visit);
}

void TriangleBvh::for_each_pair_within(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                       double distance, const std::function<void(int f, int g)>& visit) const {
  visit_placed_pairs(other, other_to_this, distance,
                     [&](int k, int l, const TriangleCorners&) { visit(order_[k], other.order_[l]); });
}

void TriangleBvh::for_each_pair_within(const TriangleBvh& other, const Eigen::Isometry3d& other_to_this,
                                       double distance, const std::function<void(const PlacedPair& pair)>& visit) const {
  visit_placed_pairs(other, other_to_this, distance, [&](int k, int l, const TriangleCorners& moved) {
    visit(PlacedPair{order_[k], other.order_[l], k, l, ordered_corners_[k], moved});
  });
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
        const TriangleCorners& t = ordered_corners_[i];
        const Eigen::Vector3d p = closest_point_on_triangle(q, t[0], t[1], t[2]).point;
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
