#include "reconfig/geometry/triangle_bvh.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <utility>

namespace reconfig::geometry {
namespace {

constexpr int kLeafSize = 4;

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
        const int f = order_[i];
        if (triangle_box(V_, F_, f).intersects(box)) visit(f);
      }
    } else {
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
  }
}

void TriangleBvh::for_each_overlapping_pair(const TriangleBvh& other,
                                            const std::function<void(int f, int g)>& visit) const {
  if (nodes_.front().begin == nodes_.front().end || other.nodes_.front().begin == other.nodes_.front().end) return;
  std::vector<std::pair<int, int>> stack{{0, 0}};
  stack.reserve(128);
  std::vector<Eigen::AlignedBox3d> other_boxes;
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const Node& a = nodes_[i];
    const Node& b = other.nodes_[j];
    if (!a.box.intersects(b.box)) continue;
    const bool a_leaf = a.left < 0, b_leaf = b.left < 0;
    if (a_leaf && b_leaf) {
      other_boxes.clear();
      for (int k = b.begin; k < b.end; ++k) other_boxes.push_back(triangle_box(other.V_, other.F_, other.order_[k]));
      for (int k = a.begin; k < a.end; ++k) {
        const int f = order_[k];
        const Eigen::AlignedBox3d fbox = triangle_box(V_, F_, f);
        if (!fbox.intersects(b.box)) continue;
        for (int l = b.begin; l < b.end; ++l)
          if (fbox.intersects(other_boxes[l - b.begin])) visit(f, other.order_[l]);
      }
      continue;
    }
    // Descend the larger (by volume-free measure: diagonal) of two inner nodes, or the inner one.
    const bool split_a = b_leaf || (!a_leaf && a.box.diagonal().squaredNorm() >= b.box.diagonal().squaredNorm());
    if (split_a) {
      stack.emplace_back(a.right, j);
      stack.emplace_back(a.left, j);
    } else {
      stack.emplace_back(i, b.right);
      stack.emplace_back(i, b.left);
    }
  }
}

}  // namespace reconfig::geometry
