#include "fcl_baselines.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/math/motion/interp_motion.h>
#include <fcl/narrowphase/detail/conservative_advancement_func_matrix.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

namespace reconfig::bench {
namespace {

/// World map of every part at time t.
std::vector<Eigen::Isometry3d> poses_at(const scene::Reconfigurable& scene, int transition, double t) {
  std::vector<Eigen::Isometry3d> poses;
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p)
    poses.push_back(scene.pose_at(transition, p, t).to_isometry(scene.parts[p].center));
  return poses;
}

/// Radius of the part about its center (0 for an empty mesh).
double part_radius(const scene::Part& part) {
  return part.mesh.V.rows() == 0 ? 0.0 : (part.mesh.V.rowwise() - part.center.transpose()).rowwise().norm().maxCoeff();
}

/// A box holding the part during FCL's interpolated motion from `from` to `to`: its center c
/// moves on the chord and the part turns about it, so every point stays within r of the
/// chord point.
Eigen::AlignedBox3d swept_box(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to, const Eigen::Vector3d& center,
                              double radius) {
  Eigen::AlignedBox3d box(from * center);
  box.extend(to * center);
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(radius);
  return {box.min() - margin, box.max() + margin};
}

/// A pair of parts over one step that the broad phase keeps.
struct PairStep {
  int a = 0, b = 0, step = 0;
};

std::vector<PairStep> swept_candidates(const scene::Reconfigurable& scene, const std::vector<std::vector<Eigen::Isometry3d>>& poses,
                                       const std::vector<bool>& moving) {
  const int n = static_cast<int>(scene.parts.size()), steps = static_cast<int>(poses.size()) - 1;
  std::vector<double> radius;
  for (const auto& part : scene.parts) radius.push_back(part_radius(part));
  std::vector<PairStep> candidates;
  std::vector<Eigen::AlignedBox3d> boxes(n);
  for (int k = 0; k < steps; ++k) {
    for (int p = 0; p < n; ++p) boxes[p] = swept_box(poses[k][p], poses[k + 1][p], scene.parts[p].center, radius[p]);
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if ((moving[a] || moving[b]) && boxes[a].intersects(boxes[b])) candidates.push_back({a, b, k});
  }
  return candidates;
}

/// Whether part p's pose changes over the transition (at any of `poses`' times).
std::vector<bool> moving_parts(const std::vector<std::vector<Eigen::Isometry3d>>& poses) {
  std::vector<bool> moving(poses.front().size(), false);
  for (std::size_t p = 0; p < moving.size(); ++p)
    for (const auto& at : poses) moving[p] = moving[p] || at[p].matrix() != poses.front()[p].matrix();
  return moving;
}

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> obbrss_model(const geometry::Mesh& mesh) {
  std::vector<fcl::Vector3d> vertices;
  std::vector<fcl::Triangle> triangles;
  for (int v = 0; v < mesh.V.rows(); ++v) vertices.emplace_back(mesh.V.row(v).transpose());
  for (int t = 0; t < mesh.F.rows(); ++t) triangles.emplace_back(mesh.F(t, 0), mesh.F(t, 1), mesh.F(t, 2));
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(vertices.size()));
  model->addSubModel(vertices, triangles);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

/// FCL's interpolated motion from `from` to `to`: the center moves linearly, the part turns
/// about it at a constant angular velocity (FCL's constructor from two transforms and a
/// reference point leaves the velocities unset, hence the one from rotations and translations).
fcl::InterpMotion<double> interpolated_motion(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to, const Eigen::Vector3d& center) {
  return {from.linear(), from.translation(), to.linear(), to.translation(), center};
}

/// FCL's continuous collision of two OBBRSS trees over one step: the time of first contact in
/// [0, 1] of the step, or none.
std::optional<double> first_contact(const fcl::CollisionGeometryd& a, const fcl::InterpMotion<double>& motion_a,
                                    const fcl::CollisionGeometryd& b, const fcl::InterpMotion<double>& motion_b) {
  using Model = fcl::BVHModel<fcl::OBBRSSd>;
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  double toc = 1;
  const bool hit = fcl::detail::conservativeAdvancementMeshOriented<fcl::OBBRSSd, fcl::detail::MeshConservativeAdvancementTraversalNodeOBBRSS<double>>(
      static_cast<const Model&>(a), &motion_a, static_cast<const Model&>(b), &motion_b, request, result, toc);
  return hit ? std::optional<double>(toc) : std::nullopt;
}

}  // namespace

FclParts fcl_parts(const scene::Reconfigurable& scene) {
  FclParts parts;
  for (const auto& part : scene.parts) {
    parts.geometry.push_back(obbrss_model(part.mesh));
  }
  return parts;
}

FclSample fcl_sample(const scene::Reconfigurable& scene, int transition, const FclParts& parts, double t, bool all_contacts) {
  const std::vector<Eigen::Isometry3d> poses = poses_at(scene, transition, t);
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  fcl::DynamicAABBTreeCollisionManagerd manager;
  for (std::size_t p = 0; p < poses.size(); ++p) {
    auto object = std::make_unique<fcl::CollisionObjectd>(parts.geometry[p], poses[p].linear(), poses[p].translation());
    object->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(p)));
    manager.registerObject(object.get());
    objects.push_back(std::move(object));
  }
  manager.setup();
  struct Data {
    FclSample sample;
    bool all_contacts;
  } data{{}, all_contacts};
  manager.collide(&data, [](fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* user) {
    auto& d = *static_cast<Data*>(user);
    fcl::CollisionRequestd request;  // default: one contact, i.e. whether they intersect
    if (d.all_contacts) request.num_max_contacts = std::numeric_limits<int>::max();
    fcl::CollisionResultd result;
    if (fcl::collide(o1, o2, request, result) > 0) {
      const int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
      const int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
      d.sample.pairs.emplace_back(std::min(a, b), std::max(a, b));
      d.sample.triangle_pairs += static_cast<long>(result.numContacts());
    }
    return false;  // go on: every colliding pair
  });
  std::sort(data.sample.pairs.begin(), data.sample.pairs.end());
  return data.sample;
}

FclCcdResult fcl_ccd_first_contacts(const scene::Reconfigurable& scene, int transition, const FclParts& parts,
                                                    const std::vector<double>& times) {
  std::vector<std::vector<Eigen::Isometry3d>> poses;
  for (double t : times) poses.push_back(poses_at(scene, transition, t));
  const std::vector<PairStep> candidates = swept_candidates(scene, poses, moving_parts(poses));
  constexpr double kNone = -1;
  std::vector<double> toc(candidates.size(), kNone);
  tbb::parallel_for(std::size_t{0}, candidates.size(), [&](std::size_t i) {
    const auto [a, b, k] = candidates[i];
    const std::optional<double> first =
        first_contact(*parts.geometry[a], interpolated_motion(poses[k][a], poses[k + 1][a], scene.parts[a].center), *parts.geometry[b],
                      interpolated_motion(poses[k][b], poses[k + 1][b], scene.parts[b].center));
    if (first) toc[i] = times[k] + *first * (times[k + 1] - times[k]);
  });
  FclCcdResult result;
  result.pair_steps = static_cast<long>(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (toc[i] != kNone) result.contacts.push_back({candidates[i].a, candidates[i].b, candidates[i].step, toc[i]});
  std::sort(result.contacts.begin(), result.contacts.end(),
            [](const auto& x, const auto& y) { return std::tie(x.a, x.b, x.step) < std::tie(y.a, y.b, y.step); });
  return result;
}

std::vector<collision::CollisionInterval> time_intervals_per_pair(const std::vector<collision::CollisionInterval>& groups) {
  std::vector<collision::CollisionInterval> sorted;
  for (const auto& g : groups) {
    collision::CollisionInterval interval;
    interval.t0 = g.t0;
    interval.t1 = g.t1;
    interval.parts = g.parts;
    sorted.push_back(std::move(interval));
  }
  std::sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) { return std::tie(x.parts, x.t0) < std::tie(y.parts, y.t0); });
  std::vector<collision::CollisionInterval> merged;
  for (auto& interval : sorted) {
    if (!merged.empty() && merged.back().parts == interval.parts && interval.t0 <= merged.back().t1)
      merged.back().t1 = std::max(merged.back().t1, interval.t1);
    else
      merged.push_back(std::move(interval));
  }
  return merged;
}

CcdComparison compare_with_engine(const std::vector<FclFirstContact>& contacts,
                                  const std::vector<collision::CollisionInterval>& engine_groups, double time_tolerance) {
  std::map<std::pair<int, int>, std::vector<double>> fcl;  // first contact times per pair, ascending
  for (const auto& c : contacts) fcl[{c.a, c.b}].push_back(c.t);
  for (auto& [pair, times] : fcl) std::sort(times.begin(), times.end());
  std::map<std::pair<int, int>, std::vector<collision::CollisionInterval>> engine;
  for (auto& interval : time_intervals_per_pair(engine_groups)) engine[{interval.parts[0], interval.parts[1]}].push_back(interval);

  CcdComparison comparison;
  const std::vector<double> none;
  for (const auto& [pair, intervals] : engine) {
    const auto found = fcl.find(pair);
    const std::vector<double>& times = found == fcl.end() ? none : found->second;
    ++comparison.pairs;
    if (times.empty())
      ++comparison.pairs_missed;
    else
      comparison.first_contact_error = std::max(comparison.first_contact_error, std::abs(times.front() - intervals.front().t0));
    for (const auto& interval : intervals) {
      ++comparison.intervals;
      const bool start = std::any_of(times.begin(), times.end(), [&](double t) { return std::abs(t - interval.t0) <= time_tolerance; });
      const bool during = std::any_of(times.begin(), times.end(), [&](double t) {
        return interval.t0 - time_tolerance <= t && t <= interval.t1 + time_tolerance;
      });
      ++(start ? comparison.starts_found : comparison.starts_missed);
      comparison.intervals_missed += during ? 0 : 1;
      comparison.ends_unreported += interval.t1 < 1 - time_tolerance ? 1 : 0;
    }
  }
  for (const auto& [pair, times] : fcl) {
    const auto it = engine.find(pair);
    for (double t : times) {
      const bool explained = it != engine.end() && std::any_of(it->second.begin(), it->second.end(), [&](const auto& interval) {
                               return interval.t0 - time_tolerance <= t && t <= interval.t1 + time_tolerance;
                             });
      comparison.extra_contacts += explained ? 0 : 1;
    }
  }
  return comparison;
}

}  // namespace reconfig::bench
