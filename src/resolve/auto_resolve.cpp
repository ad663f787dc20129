#include "reconfig/resolve/auto_resolve.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/common/input_error.h"
#include "reconfig/resolve/hints.h"
#include "reconfig/resolve/key_dofs.h"
#include "reconfig/resolve/pair_energy.h"
#include "reconfig/scene/edits.h"

namespace reconfig::resolve {
namespace {

using Pair = std::pair<int, int>;
using Window = std::pair<double, double>;

std::vector<collision::CollisionInterval> detect(const scene::Reconfigurable& scene, const AutoResolveRequest& request) {
  collision::CollisionRequest detection;
  detection.detector = request.detector;
  detection.transitions = {request.transition};
  const collision::CollisionResult result = collision::detect_collisions(scene, detection);
  return result.transitions.empty() ? std::vector<collision::CollisionInterval>{} : result.transitions[0].intervals;
}

/// The time windows of each pair of parts that collide: their intervals, widened so that the
/// energy still sees the collision as the keys move it in time, and merged where they overlap.
std::map<Pair, std::vector<Window>> pair_windows(const std::vector<collision::CollisionInterval>& intervals) {
  std::map<Pair, std::vector<Window>> windows;
  for (const auto& ci : intervals) {
    const double pad = std::max(0.02, 0.5 * ci.duration());
    for (std::size_t i = 0; i < ci.parts.size(); ++i)
      for (std::size_t j = i + 1; j < ci.parts.size(); ++j)
        windows[{ci.parts[i], ci.parts[j]}].push_back({std::max(0.0, ci.t0 - pad), std::min(1.0, ci.t1 + pad)});
  }
  for (auto& [pair, list] : windows) {
    std::sort(list.begin(), list.end());
    std::vector<Window> merged;
    for (const Window& w : list) {
      if (!merged.empty() && w.first <= merged.back().second) merged.back().second = std::max(merged.back().second, w.second);
      else merged.push_back(w);
    }
    list = std::move(merged);
  }
  return windows;
}

/// The energy of a pair over its windows, with every window's samples (for the gradient).
struct WindowedEnergy {
  double energy = 0;
  double severity_time = 0;
  std::vector<PairEnergy> windows;
};

WindowedEnergy windowed_energy(const scene::Reconfigurable& scene, ShapeCache& shapes, int transition, Pair pair,
                               const std::vector<Window>& windows) {
  WindowedEnergy result;
  double largest = -1;
  for (const Window& w : windows) {
    PairEnergyRequest request;
    request.transition = transition;
    request.part_a = pair.first;
    request.part_b = pair.second;
    request.t0 = w.first;
    request.t1 = w.second;
    PairEnergy energy = pair_energy(scene, shapes, request);
    result.energy += energy.energy;
    if (energy.energy > largest) {
      largest = energy.energy;
      result.severity_time = energy.severity_time;
    }
    result.windows.push_back(std::move(energy));
  }
  return result;
}

bool is_keyframed(const scene::Reconfigurable& scene, int transition, int part) {
  const auto& tracks = scene.transitions[transition].tracks;
  const auto it = tracks.find(scene.parts[part].name);
  return it != tracks.end() && std::holds_alternative<scene::KeyframedTrack>(it->second);
}

/// Inserts a translation key (and a rotation key if the part turns) at `t` unless the part has
/// an inner key within `window`; returns what it inserted.
std::vector<std::string> ensure_inner_keys(scene::Reconfigurable& scene, int transition, int part, Window window,
                                           double t) {
  std::vector<std::string> inserted;
  const auto& track = std::get<scene::KeyframedTrack>(scene.transitions[transition].tracks.at(scene.parts[part].name));
  const auto has_inner_key = [&](const auto& keys) {
    for (std::size_t j = 1; j + 1 < keys.size(); ++j)
      if (keys[j].time >= window.first && keys[j].time <= window.second) return true;
    return false;
  };
  const bool turns = track.rotation.size() >= 2;
  const bool need_translation = !has_inner_key(track.translation);
  const bool need_rotation = turns && !has_inner_key(track.rotation);
  const auto insert = [&](scene::KeyKind kind, const char* what) {
    try {
      scene::insert_key(scene.transitions[transition].name, scene.parts[part].name, kind, t)->apply(scene);
      inserted.push_back(fmt::format("{} {} {:.4f}", scene.parts[part].name, what, t));
    } catch (const InputError&) {
      // A key already at t (or t at an end): the existing keys are the degrees of freedom.
    }
  };
  if (need_translation) insert(scene::KeyKind::kTranslation, "translation");
  if (need_rotation) insert(scene::KeyKind::kRotation, "rotation");
  return inserted;
}

/// The design's keys as a point z of the descent (in length units: rotations scaled by the
/// part's radius, times by the pair's size), and back.
class DescentSpace {
 public:
  DescentSpace(const scene::Reconfigurable& base, int transition, std::vector<int> parts, const DofSelection& selection,
               double length)
      : base_(base), transition_(transition), parts_(std::move(parts)), length_(length) {
    for (int part : parts_) {
      dofs_.push_back(key_dofs(base, transition, part, selection));
      const scene::Part& p = base.parts[part];
      double radius = 0;
      for (int v = 0; v < p.mesh.vertex_count(); ++v)
        radius = std::max(radius, (p.mesh.V.row(v).transpose() - p.center).norm());
      for (const KeyDof& dof : dofs_.back())
        for (int c = 0; c < dof.size(); ++c)
          scale_.push_back(dof.kind == DofKind::kRotation ? std::max(radius, 1e-9)
                                                          : dof.kind == DofKind::kTime ? length : 1.0);
    }
  }
  int size() const { return static_cast<int>(scale_.size()); }

  /// The design at z (z = 0 is the base design).
  scene::Reconfigurable at(const Eigen::VectorXd& z) const {
    scene::Reconfigurable moved = base_;
    int offset = 0;
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const int n = dof_coordinates(dofs_[i]);
      Eigen::VectorXd step(n);
      for (int k = 0; k < n; ++k) step[k] = z[offset + k] / scale_[offset + k];
      displace_keys(moved, transition_, parts_[i], dofs_[i], step);
      offset += n;
    }
    return moved;
  }

  /// ∂E/∂z at the design `scene` (= at(z)) from the pair's energy samples.
  Eigen::VectorXd gradient(const scene::Reconfigurable& scene, const WindowedEnergy& energy, Pair pair) const {
    Eigen::VectorXd g(size());
    int offset = 0;
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const int n = dof_coordinates(dofs_[i]);
      Eigen::VectorXd gx = Eigen::VectorXd::Zero(n);
      for (const PairEnergy& window : energy.windows)
        gx += energy_gradient(scene, transition_, parts_[i], dofs_[i], window, parts_[i] == pair.first);
      for (int k = 0; k < n; ++k) g[offset + k] = gx[k] / scale_[offset + k];
      offset += n;
    }
    return g;
  }

 private:
  const scene::Reconfigurable& base_;
  int transition_;
  std::vector<int> parts_;
  double length_;
  std::vector<std::vector<KeyDof>> dofs_;
  std::vector<double> scale_;
};

/// The energy of the pair at z, or +infinity where z makes no valid design.
double energy_at(const DescentSpace& space, const Eigen::VectorXd& z, ShapeCache& shapes, int transition, Pair pair,
                 const std::vector<Window>& windows) {
  try {
    return windowed_energy(space.at(z), shapes, transition, pair, windows).energy;
  } catch (const InputError&) {
    return std::numeric_limits<double>::infinity();
  }
}

/// The step along the unit direction d from z that lowers the energy most: the best of a
/// halving sequence from `reach` (the energy landscape along a line may have a barrier, e.g.
/// where a contained part's surface starts to cross), then golden-section search around it;
/// where the energy reaches 0, the smallest zero step found by bisection, plus `clearance`.
double line_search(const std::function<double(double)>& energy, double e0, double reach, double clearance) {
  constexpr int kHalvings = 10;
  std::vector<double> steps, values;
  for (int k = 0; k < kHalvings; ++k) {
    steps.push_back(reach / std::pow(2.0, k));
    values.push_back(energy(steps.back()));
  }
  const int best = static_cast<int>(std::min_element(values.begin(), values.end()) - values.begin());
  if (!(values[best] < e0)) return 0;
  if (values[best] == 0) {
    double lo = best + 1 < kHalvings ? steps[best + 1] : 0.0, hi = steps[best];
    for (int i = 0; i < 8; ++i) {
      const double mid = 0.5 * (lo + hi);
      (energy(mid) == 0 ? hi : lo) = mid;
    }
    const double cleared = std::min(reach, hi + clearance);
    return energy(cleared) == 0 ? cleared : hi;
  }
  // Golden-section search on the bracket around the best step.
  double lo = best + 1 < kHalvings ? steps[best + 1] : 0.0, hi = best > 0 ? steps[best - 1] : reach;
  constexpr double kInvPhi = 0.6180339887498949;
  double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
  double f1 = energy(x1), f2 = energy(x2);
  for (int i = 0; i < 12; ++i) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - kInvPhi * (hi - lo), f1 = energy(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + kInvPhi * (hi - lo), f2 = energy(x2);
    }
  }
  const double golden = f1 < f2 ? x1 : x2;
  return std::min(f1, f2) < values[best] ? golden : steps[best];
}

/// Size of the pair: the larger of the two parts' box diagonals.
double pair_size(const scene::Reconfigurable& scene, Pair pair) {
  const auto diagonal = [&](int part) {
    const Eigen::MatrixX3d& V = scene.parts[part].mesh.V;
    return (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
  };
  return std::max(diagonal(pair.first), diagonal(pair.second));
}

struct RoundOutcome {
  scene::Reconfigurable scene;
  ResolveRound round;
};

/// One round's descent on one pair.
RoundOutcome descend(scene::Reconfigurable scene, ShapeCache& shapes, const AutoResolveRequest& request, Pair pair,
                     const std::vector<Window>& windows, ResolveRound round) {
  const int tr = request.transition;
  WindowedEnergy energy = windowed_energy(scene, shapes, tr, pair, windows);
  round.energy_before = round.energy_after = energy.energy;
  std::vector<int> movable;
  for (int part : {pair.first, pair.second})
    if (is_keyframed(scene, tr, part)) movable.push_back(part);
  if (movable.empty() || energy.energy == 0) return {std::move(scene), round};
  for (int part : movable)
    for (const Window& w : windows)
      for (std::string& key : ensure_inner_keys(scene, tr, part, w, energy.severity_time))
        round.inserted_keys.push_back(std::move(key));
  const double size = pair_size(scene, pair);
  const double clearance = std::max(4 * request.detector.tolerance, 0.01 * size);
  for (int step = 0; step < request.max_steps && energy.energy > 0; ++step) {
    const DescentSpace space(scene, tr, movable, {.handles = true, .rotations = true, .times = request.move_times}, size);
    const Eigen::VectorXd g = space.gradient(scene, energy, pair);
    if (g.norm() == 0 || !std::isfinite(g.norm())) break;
    const Eigen::VectorXd d = -g / g.norm();
    const double alpha = line_search(
        [&](double a) { return energy_at(space, a * d, shapes, tr, pair, windows); }, energy.energy, size, clearance);
    if (alpha == 0) break;
    scene = space.at(alpha * d);
    energy = windowed_energy(scene, shapes, tr, pair, windows);
    round.steps = step + 1;
  }
  round.energy_after = energy.energy;
  return {std::move(scene), round};
}

}  // namespace

AutoResolveResult auto_resolve(const scene::Reconfigurable& input, const AutoResolveRequest& request) {
  AutoResolveResult result;
  result.scene = input;
  ShapeCache shapes;
  std::set<Pair> stuck;  // pairs whose last round lowered nothing
  for (int r = 0; r < request.max_rounds; ++r) {
    if (!report_progress(request.progress, static_cast<double>(r) / request.max_rounds)) {
      result.cancelled = true;
      result.stopped_because = "cancelled";
      break;
    }
    const std::vector<collision::CollisionInterval> intervals = detect(result.scene, request);
    result.intervals_left = static_cast<int>(intervals.size());
    if (intervals.empty()) {
      result.collision_free = true;
      result.stopped_because = "the transition is collision-free";
      break;
    }
    // The pair that contributes most energy, among those not known to be stuck.
    const auto windows = pair_windows(intervals);
    Pair chosen{-1, -1};
    double largest = -1;
    for (const auto& [pair, list] : windows) {
      if (stuck.count(pair)) continue;
      const double e = windowed_energy(result.scene, shapes, request.transition, pair, list).energy;
      if (e > largest) largest = e, chosen = pair;
    }
    if (chosen.first < 0) {
      result.stopped_because = "no step lowers the energy of the pairs that still collide";
      break;
    }
    ResolveRound round;
    round.round = r;
    round.pair = {chosen.first, chosen.second};
    round.intervals_before = static_cast<int>(intervals.size());
    RoundOutcome outcome = descend(result.scene, shapes, request, chosen, windows.at(chosen), round);
    result.scene = std::move(outcome.scene);
    if (!(outcome.round.energy_after < outcome.round.energy_before)) stuck.insert(chosen);
    else stuck.clear();  // the design changed: other pairs may move again
    if (request.on_round) request.on_round(outcome.round);
    result.rounds.push_back(std::move(outcome.round));
  }
  if (result.stopped_because.empty()) {
    const auto intervals = detect(result.scene, request);
    result.intervals_left = static_cast<int>(intervals.size());
    result.collision_free = intervals.empty();
    result.stopped_because = result.collision_free ? "the transition is collision-free"
                                                   : fmt::format("stopped after {} rounds", request.max_rounds);
  }
  return result;
}

}  // namespace reconfig::resolve
