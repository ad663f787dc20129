#include "reconfig/linkage/joint_order.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "linkage/detail/newton_block.h"
#include "reconfig/common/input_error.h"

namespace reconfig::linkage {
namespace {

class Orderer {
 public:
  explicit Orderer(const Linkage& linkage)
      : linkage_(linkage),
        X0_(linkage.initial_positions()),
        links_of_(linkage.links_of_joints()),
        neighbours_(linkage.neighbours()),
        known_(linkage.joints.size(), false) {}

  JointOrder run() {
    // The initial nodes (fixed joints and the motor joint) are all known before any link is
    // completed, so that no rule is derived for one of them.
    std::vector<int> initial;
    for (std::size_t k = 0; k < linkage_.joints.size(); ++k)
      if (linkage_.joints[k].fixed) {
        order_.rules.push_back({RuleKind::kFixed, static_cast<int>(k)});
        initial.push_back(static_cast<int>(k));
      }
    order_.rules.push_back({RuleKind::kMotor, linkage_.motor.joint, linkage_.motor.center});
    initial.push_back(linkage_.motor.joint);
    for (int k : initial) mark_known(k);
    for (int k : initial) complete_links(k);
    while (true) {
      // Algorithm 1: cycle through the active list until a whole pass makes no progress.
      std::size_t failures = 0;
      while (!active_.empty() && failures < active_.size()) {
        const int k = active_.front();
        active_.pop_front();
        if (known_[k]) continue;
        if (try_rule(k)) {
          failures = 0;
        } else {
          active_.push_back(k);
          ++failures;
        }
      }
      if (active_.empty()) break;
      if (!add_newton_block()) break;
    }
    std::vector<int> unknown;
    for (std::size_t k = 0; k < known_.size(); ++k)
      if (!known_[k]) unknown.push_back(static_cast<int>(k));
    if (!unknown.empty()) {
      std::string names;
      for (int k : unknown) names += (names.empty() ? "\"" : ", \"") + linkage_.joints[k].name + "\"";
      throw InputError("", "joints[" + std::to_string(unknown.front()) + "]",
                       std::string(unknown.size() == 1 ? "joint " : "joints ") + names +
                           (unknown.size() == 1 ? " is" : " are") +
                           " not determined by the links (the linkage is under-constrained)");
    }
    std::sort(order_.stuck_joints.begin(), order_.stuck_joints.end());
    return order_;
  }

 private:
  void visit(const Rule& rule) {
    order_.rules.push_back(rule);
    mark_known(rule.k);
    complete_links(rule.k);
  }

  void mark_known(int k) {
    known_[k] = true;
    for (int n : neighbours_[k])
      if (!known_[n]) active_.push_back(n);
  }

  // "As soon as rules for two joint positions on a given component are known, we add
  // corresponding rules for all remaining joints on that component."
  void complete_links(int k) {
    for (int l : links_of_[k]) {
      const auto [i, j] = best_known_pair(l);
      if (i < 0) continue;
      for (int m : linkage_.links[l])
        if (!known_[m]) visit({RuleKind::kRigid, m, i, j});
    }
  }

  // The two known joints of link l farthest apart, or (-1, -1).
  std::pair<int, int> best_known_pair(int l) const {
    std::pair<int, int> best{-1, -1};
    double best_length = 0;
    const auto& link = linkage_.links[l];
    for (std::size_t a = 0; a < link.size(); ++a)
      for (std::size_t b = a + 1; b < link.size(); ++b)
        if (known_[link[a]] && known_[link[b]]) {
          const double length = (X0_.col(link[a]) - X0_.col(link[b])).norm();
          if (length > best_length) best = {link[a], link[b]}, best_length = length;
        }
    return best;
  }

  bool try_rule(int k) {
    for (int l : links_of_[k]) {
      const auto [i, j] = best_known_pair(l);
      if (i >= 0) {
        visit({RuleKind::kRigid, k, i, j});
        return true;
      }
    }
    std::vector<int> known_neighbours;
    for (int n : neighbours_[k])
      if (known_[n]) known_neighbours.push_back(n);
    if (known_neighbours.size() < 2) return false;
    // The best-conditioned reconstruction triangle: largest sin² of the angle at k.
    int best_i = known_neighbours[0], best_j = known_neighbours[1];
    double best_quality = -1;
    for (std::size_t a = 0; a < known_neighbours.size(); ++a)
      for (std::size_t b = a + 1; b < known_neighbours.size(); ++b) {
        const Eigen::Vector2d u = X0_.col(known_neighbours[a]) - X0_.col(k);
        const Eigen::Vector2d v = X0_.col(known_neighbours[b]) - X0_.col(k);
        const double c = u.dot(v) / (u.norm() * v.norm());
        const double quality = 1 - c * c;
        if (quality > best_quality) best_quality = quality, best_i = known_neighbours[a], best_j = known_neighbours[b];
      }
    visit({RuleKind::kTriangle, k, best_i, best_j});
    return true;
  }

  // The equations of the block `joints` given the known joints, or an empty block when they
  // do not number exactly 2·#joints.
  NewtonBlock block_equations(const std::vector<int>& joints) const {
    NewtonBlock block;
    block.joints = joints;
    std::vector<bool> in_block(known_.size(), false);
    for (int k : joints) in_block[k] = true;
    std::vector<bool> link_done(linkage_.links.size(), false);
    int equations = 0;
    for (int k : joints)
      for (int l : links_of_[k]) {
        if (link_done[l]) continue;
        link_done[l] = true;
        std::vector<int> involved;
        int known_one = -1;
        for (int m : linkage_.links[l])
          if (in_block[m] || known_[m]) {
            involved.push_back(m);
            if (known_[m] && known_one < 0) known_one = m;
          }
        if (involved.size() < 2) continue;
        NewtonBlock::LinkEquations eq;
        eq.r0 = known_one >= 0 ? known_one : involved.front();
        double farthest = -1;
        for (int m : involved)
          if (m != eq.r0 && (X0_.col(m) - X0_.col(eq.r0)).norm() > farthest)
            farthest = (X0_.col(m) - X0_.col(eq.r0)).norm(), eq.r1 = m;
        for (int m : involved)
          if (m != eq.r0 && m != eq.r1) eq.others.push_back(m);
        equations += 1 + 2 * static_cast<int>(eq.others.size());
        block.links.push_back(eq);
      }
    if (equations != 2 * static_cast<int>(joints.size())) block.links.clear();
    return block;
  }

  bool determined(const NewtonBlock& block) const {
    if (block.links.empty()) return false;
    detail::BlockSystem system(block, X0_);
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    system.evaluate(X0_, r, &J);
    const Eigen::MatrixXd Jy = J.leftCols(system.unknowns());
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jy);
    const auto& s = svd.singularValues();
    return s.size() > 0 && s(s.size() - 1) > 1e-9 * std::max(1.0, s(0));
  }

  // Grows groups of unknown joints breadth-first from each stuck joint; keeps the smallest
  // group whose link equations determine it.
  bool add_newton_block() {
    constexpr std::size_t kMaxBlock = 16;
    NewtonBlock best;
    std::vector<int> starts(active_.begin(), active_.end());
    std::sort(starts.begin(), starts.end());
    starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
    for (int start : starts) {
      if (known_[start]) continue;
      std::vector<int> group{start};
      std::deque<int> frontier{start};
      std::vector<bool> seen(known_.size(), false);
      seen[start] = true;
      while (group.size() <= kMaxBlock && (best.joints.empty() || group.size() < best.joints.size())) {
        NewtonBlock block = block_equations(group);
        if (determined(block)) {
          best = block;
          break;
        }
        int next = -1;
        while (!frontier.empty() && next < 0) {
          for (int n : neighbours_[frontier.front()])
            if (!known_[n] && !seen[n]) {
              next = n;
              break;
            }
          if (next < 0) frontier.pop_front();
        }
        if (next < 0) break;
        seen[next] = true;
        group.push_back(next);
        frontier.push_back(next);
      }
    }
    if (best.joints.empty()) return false;
    order_.blocks.push_back(best);
    order_.rules.push_back({RuleKind::kNewtonBlock, -1, -1, -1, static_cast<int>(order_.blocks.size()) - 1});
    for (int k : best.joints) order_.stuck_joints.push_back(k);
    for (int k : best.joints) mark_known(k);
    for (int k : best.joints) complete_links(k);
    return true;
  }

  const Linkage& linkage_;
  Eigen::Matrix2Xd X0_;
  std::vector<std::vector<int>> links_of_;
  std::vector<std::vector<int>> neighbours_;
  std::vector<bool> known_;
  std::deque<int> active_;
  JointOrder order_;
};

}  // namespace

JointOrder order_joints(const Linkage& linkage) { return Orderer(linkage).run(); }

std::string describe_rule(const Linkage& linkage, const JointOrder& order, const Rule& rule) {
  auto name = [&](int j) { return "\"" + linkage.joints[j].name + "\""; };
  switch (rule.kind) {
    case RuleKind::kFixed: return name(rule.k) + " fixed";
    case RuleKind::kMotor: return name(rule.k) + " turned by the motor about " + name(rule.i);
    // Appended, not `"(" + name(…)`: GCC 12 warns (-Wrestrict) about the insertion at the front
    // that `const char* + std::string&&` may do, a false positive (GCC bug 105651).
    case RuleKind::kTriangle:
      return std::string("(").append(name(rule.i)).append(", ").append(name(rule.j)).append(") -> ").append(name(rule.k));
    case RuleKind::kRigid: return name(rule.k) + " rigid with " + name(rule.i) + ", " + name(rule.j);
    case RuleKind::kNewtonBlock: {
      std::string names;
      for (int k : order.blocks[rule.block].joints) names += (names.empty() ? "" : ", ") + name(k);
      return "complex loop {" + names + "} solved by Newton";
    }
  }
  return {};
}

}  // namespace reconfig::linkage
