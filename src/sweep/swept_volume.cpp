// The only file of the sweep module that includes OpenVDB (its headers are heavy).
#include "reconfig/sweep/swept_volume.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>

#include "reconfig/geometry/bounding_box.h"
#include "reconfig/geometry/mass_properties.h"
#include "sweep/detail/clearance_check.h"
#include "sweep/detail/outer_shells.h"
#include "sweep/detail/part_distance.h"

namespace reconfig::sweep {
namespace {

using openvdb::Coord;
using openvdb::FloatGrid;
using openvdb::FloatTree;

constexpr int kLeafDim = 8;  // FloatTree::LeafNodeType::DIM
const double kSqrt3 = std::sqrt(3.0);
/// The tight level's buffer over ε + δ, in cells: room for the contour's chords (see the header).
constexpr double kTightBuffer = 0.15;
/// The levels tried above the tight one, in cells, until one passes the clearance check; the
/// last one is beyond the cell bound (which is used instead).
constexpr double kLevelSteps[] = {0.0, 0.25, 0.6, 2.0};

void initialize_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

/// The maps from the swept grid's index space to B's index space (same step h), one per sample.
struct IndexMap {
  Eigen::Matrix3d linear;
  Eigen::Vector3d offset;
  Eigen::Vector3d apply(const Eigen::Vector3d& x) const { return linear * x + offset; }
};

std::vector<IndexMap> index_maps(const RelativeMotion& motion, const std::vector<double>& times, double h) {
  std::vector<IndexMap> maps;
  for (double t : times) {
    const Eigen::Isometry3d inverse = motion.at(t).inverse();
    maps.push_back({inverse.linear(), inverse.translation() / h});
  }
  return maps;
}

/// Box (world, A's frame) holding B at every sample, padded by `pad`.
Eigen::AlignedBox3d swept_box(const geometry::Mesh& part, const RelativeMotion& motion, const std::vector<double>& times,
                              double pad) {
  const Eigen::AlignedBox3d rest(part.V.colwise().minCoeff().transpose(), part.V.colwise().maxCoeff().transpose());
  Eigen::AlignedBox3d box;
  for (double t : times) {
    const Eigen::Isometry3d g = motion.at(t);
    for (int c = 0; c < 8; ++c) box.extend(g * rest.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
  }
  box.min().array() -= pad;
  box.max().array() += pad;
  return box;
}

/// A run [first, end) of consecutive time samples; no point of the part moves more than
/// `reach` (scene units) from its pose at `first` within the run.
struct SampleChunk {
  int first = 0, end = 0;
  double reach = 0;
};

/// Runs of `size` samples (the last one shorter).
std::vector<SampleChunk> sample_chunks(const RelativeMotion& motion, const std::vector<double>& times, int size) {
  std::vector<SampleChunk> chunks;
  for (int first = 0; first < int(times.size()); first += size) {
    const int end = std::min(int(times.size()), first + size);
    chunks.push_back({first, end, motion.displacement_bound(times[first], times[end - 1])});
  }
  return chunks;
}

/// What one leaf of the swept grid turned out to be.
struct LeafResult {
  enum Kind { kOutside, kInside, kBand } kind = kOutside;
  std::unique_ptr<FloatTree::LeafNodeType> leaf;
  int voxels = 0;
};

/// The evaluation of the swept field G̃ − ℓ on one leaf (values clamped to [−W, W]), by
/// recursive subdivision of the leaf into blocks of 4³ and 2³, then the voxels of a 2³ block by
/// branch and bound over its samples (`evaluate_voxel`). A block of n³
/// voxels around center c: every voxel x has φ̃_k(x) >= φ̃_k(c) − s_n with s_n = the block's
/// half diagonal + 2e (φ is 1-Lipschitz, a look-up is within e of it), so with
/// m = min_k φ̃_k(c): the block is inside when m + s_n < ℓ − W, outside when m − s_n > ℓ + W, and
/// otherwise only the samples with φ̃_k(c) − s_n < min(m + s_n, ℓ + W) can set a voxel's minimum.
/// G̃(x) = min_k D̃_k(x), D̃_k a lower bound of the distance to the solid of pose k
/// (`PartDistance::lower_bound`), is a lower bound of the sampled swept distance.
class LeafEvaluator {
 public:
  /// @param chunks  runs of consecutive samples, each with how far the part moves within it
  LeafEvaluator(const detail::PartDistance& part_grid, const std::vector<IndexMap>& maps, std::vector<SampleChunk> chunks,
                double h, double level, double band, double lookup_error)
      : part_grid_(part_grid), maps_(maps), chunks_(std::move(chunks)), h_(h), level_(level), band_(band),
        lookup_error_(lookup_error) {}

  LeafResult evaluate(const Coord& origin) const {
    std::vector<float> values(FloatTree::LeafNodeType::SIZE, float(band_));  // F − ℓ, x-major
    const Eigen::Vector3d leaf_origin(origin.x(), origin.y(), origin.z());
    const Kind kind = refine(leaf_origin, Eigen::Vector3i::Zero(), kLeafDim, candidates(leaf_origin), values);
    if (kind == kInsideBlock) return {LeafResult::kInside, nullptr, 0};
    if (kind == kOutsideBlock) return {};
    auto leaf = std::make_unique<FloatTree::LeafNodeType>(origin, float(band_), false);
    for (openvdb::Index n = 0; n < FloatTree::LeafNodeType::SIZE; ++n) leaf->setValueOn(n, values[n]);
    return {LeafResult::kBand, std::move(leaf), FloatTree::LeafNodeType::SIZE};
  }

  /// G̃ at a world point, capped at ℓ + W: a lower bound of the distance from x to the union
  /// of the sampled poses. A run of samples is skipped when its first pose proves every pose
  /// of the run (within `reach` of it) no nearer than the least value found yet.
  double point_lower_bound(const Eigen::Vector3d& world) const {
    const Eigen::Vector3d x = world / h_;
    double best = level_ + band_;
    for (const SampleChunk& chunk : chunks_) {
      if (part_grid_.nearest(maps_[chunk.first].apply(x)) - chunk.reach - 2 * lookup_error_ >= best) continue;
      for (int k = chunk.first; k < chunk.end; ++k) best = std::min(best, sample_lower_bound(k, x, best));
    }
    return best;
  }

 private:
  enum Kind { kInsideBlock, kOutsideBlock, kMixedBlock };

  /// The samples that may matter on the leaf. A run of samples is dropped when its first pose
  /// proves every pose k of the run farther than ℓ + W + e from every voxel of the leaf:
  /// φ_k(x) >= φ_first(x) − D (a point inside pose k lies within D of pose first), a look-up
  /// is within e of φ (or a lower bound beyond the part's band), and the leaf's voxels lie
  /// within its half diagonal of its center. Such a sample only gives voxels values above
  /// ℓ + W, which the band clamps to W anyway.
  std::vector<int> candidates(const Eigen::Vector3d& leaf_origin) const {
    const Eigen::Vector3d center = leaf_origin + Eigen::Vector3d::Constant(0.5 * (kLeafDim - 1));
    const double slack = 0.5 * (kLeafDim - 1) * kSqrt3 * h_ + 2 * lookup_error_;
    std::vector<int> kept;
    for (const SampleChunk& chunk : chunks_) {
      const double lower = part_grid_.nearest(maps_[chunk.first].apply(center)) - chunk.reach - 2 * lookup_error_;
      if (lower > level_ + band_ + slack) continue;
      for (int k = chunk.first; k < chunk.end; ++k) kept.push_back(k);
    }
    return kept;
  }

  /// Fills the n³ block at `local` (voxel offset in the leaf) of `values`; says what it was.
  Kind refine(const Eigen::Vector3d& leaf_origin, const Eigen::Vector3i& local, int n, const std::vector<int>& candidates,
              std::vector<float>& values) const {
    const Eigen::Vector3d center = leaf_origin + local.cast<double>() + Eigen::Vector3d::Constant(0.5 * (n - 1));
    std::vector<float> at_center(candidates.size());
    float m = std::numeric_limits<float>::infinity();
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      at_center[c] = part_grid_.nearest(maps_[candidates[c]].apply(center));
      m = std::min(m, at_center[c]);
    }
    const double slack = 0.5 * (n - 1) * kSqrt3 * h_ + 2 * lookup_error_;
    if (m + slack < level_ - band_) {
      fill(local, n, float(-band_), values);
      return kInsideBlock;
    }
    if (m - slack > level_ + band_) return kOutsideBlock;  // values stay +W
    const double keep_below = std::min(m + slack, level_ + band_) + slack;
    if (n == 2) {
      // Sorted by a lower bound of φ_k at the center (the look-up minus its own rounding
      // distance): a voxel lies within the half diagonal of the center, φ_k is 1-Lipschitz.
      std::vector<std::pair<double, int>> nearest_first;
      for (std::size_t c = 0; c < candidates.size(); ++c)
        if (at_center[c] < keep_below)
          nearest_first.emplace_back(part_grid_.nearest_lower_bound(maps_[candidates[c]].apply(center)), candidates[c]);
      std::sort(nearest_first.begin(), nearest_first.end());
      for (int child = 0; child < 8; ++child) {
        const Eigen::Vector3i voxel = local + Eigen::Vector3i(child >> 2, (child >> 1) & 1, child & 1);
        evaluate_voxel(leaf_origin, voxel, 0.5 * kSqrt3 * h_, nearest_first, values);
      }
      return kMixedBlock;
    }
    std::vector<int> kept;
    for (std::size_t c = 0; c < candidates.size(); ++c)
      if (at_center[c] < keep_below) kept.push_back(candidates[c]);
    const int half = n / 2;
    int inside = 0, outside = 0;
    for (int child = 0; child < 8; ++child) {
      const Eigen::Vector3i offset(child >> 2, (child >> 1) & 1, child & 1);
      const Kind kind = refine(leaf_origin, local + half * offset, half, kept, values);
      inside += kind == kInsideBlock;
      outside += kind == kOutsideBlock;
    }
    return inside == 8 ? kInsideBlock : outside == 8 ? kOutsideBlock : kMixedBlock;
  }

  /// D̃_k at index-space point x when it may be below `best` (one look-up tells), else `best`.
  double sample_lower_bound(int k, const Eigen::Vector3d& x, double best) const {
    const Eigen::Vector3d y = maps_[k].apply(x);
    if (part_grid_.nearest_lower_bound(y) >= best) return best;
    return std::min(best, part_grid_.lower_bound(y));
  }

  /// One voxel of a 2³ block, G̃ − ℓ clamped to [−W, W], by branch and bound over the block's
  /// samples sorted by a lower bound of their value at its center: a sample whose bound there
  /// minus `slack` (half the block's diagonal) is not below the least value found yet, nor
  /// below ℓ + W, cannot lower it, and neither can any later one.
  void evaluate_voxel(const Eigen::Vector3d& leaf_origin, const Eigen::Vector3i& local, double slack,
                      const std::vector<std::pair<double, int>>& nearest_first, std::vector<float>& values) const {
    const Eigen::Vector3d x = leaf_origin + local.cast<double>();
    double best = level_ + band_;
    const double floor = std::max(0.0, level_ - band_);  // D̃ >= 0: nothing lowers it further
    for (const auto& [at_center, k] : nearest_first) {
      if (at_center - slack >= best || best <= floor) break;
      best = sample_lower_bound(k, x, best);
    }
    values[(local.x() << 6) | (local.y() << 3) | local.z()] = float(std::clamp(best - level_, -band_, band_));
  }

  static void fill(const Eigen::Vector3i& local, int n, float value, std::vector<float>& values) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int l = 0; l < n; ++l) values[((local.x() + i) << 6) | ((local.y() + j) << 3) | (local.z() + l)] = value;
  }

  const detail::PartDistance& part_grid_;
  const std::vector<IndexMap>& maps_;
  std::vector<SampleChunk> chunks_;
  double h_, level_, band_, lookup_error_;
};

geometry::Mesh mesh_from_vdb(const std::vector<openvdb::Vec3s>& points, const std::vector<openvdb::Vec3I>& triangles,
                             const std::vector<openvdb::Vec4I>& quads) {
  geometry::Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) mesh.V.row(i) << points[i].x(), points[i].y(), points[i].z();
  mesh.F.resize(static_cast<Eigen::Index>(triangles.size() + 2 * quads.size()), 3);
  Eigen::Index f = 0;
  for (const auto& t : triangles) mesh.F.row(f++) << int(t[0]), int(t[1]), int(t[2]);
  for (const auto& q : quads) {
    mesh.F.row(f++) << int(q[0]), int(q[1]), int(q[2]);
    mesh.F.row(f++) << int(q[0]), int(q[2]), int(q[3]);
  }
  if (geometry::mass_properties(mesh).volume < 0) mesh.F.col(1).swap(mesh.F.col(2));
  return mesh;
}

/// The outer shells of the surface G̃ − tight level = `isovalue`.
geometry::Mesh contour(const FloatGrid& grid, double isovalue, int& filled_cavities) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, isovalue, 0.0);
  return detail::outer_shells(mesh_from_vdb(points, triangles, quads), filled_cavities);
}

}  // namespace

SweptVolumeResult swept_volume(const geometry::Mesh& part, const RelativeMotion& motion,
                               const SweptVolumeRequest& request) {
  SweptVolumeResult result;
  if (part.empty()) return result;
  initialize_openvdb();
  // h: given, or 1/128 of the longest side of the box swept by B's box (coarse samples).
  double h = request.grid_step;
  if (h <= 0) {
    double unused = 0;
    const double size = part.V.colwise().maxCoeff().maxCoeff() - part.V.colwise().minCoeff().minCoeff();
    Eigen::AlignedBox3d coarse = swept_box(part, motion, motion.time_samples(0.05 * size, unused), 2 * request.offset);
    if (request.clip) coarse = coarse.intersection(*request.clip);
    if (coarse.isEmpty()) return result;  // the sweep misses the clip box
    h = std::max(coarse.sizes().maxCoeff(), 1e-3 * size) / 128;
  }
  result.grid_step = h;
  const std::vector<double> times = motion.time_samples(request.time_fraction * h, result.motion_error);
  result.time_samples = static_cast<int>(times.size());
  const double lookup_error = 0.5 * kSqrt3 * h;  // of a nearest-grid-point look-up (culling only)
  const double epsilon = request.offset, delta = result.motion_error, grown = 1 + 1e-9;
  const double safe_level = (epsilon + delta + kSqrt3 * h) * grown + 1e-12;
  const double tight_level = std::max(epsilon + delta + kTightBuffer * h, kSqrt3 * h + delta) * grown + 1e-12;
  result.level = tight_level;
  const double band = 2 * h;  // |G̃ − ℓ| is stored up to this (> safe − tight), beyond it only the side
  // Outside, beyond ℓ + W + (the slack of a 2³ block) a look-up only needs to be a lower bound.
  const double part_band_voxels = std::ceil((result.level + band + 0.5 * kSqrt3 * h + 2 * lookup_error) / h) + 2;

  if (!report_progress(request.progress, 0.0)) return result.cancelled = true, result;
  // Inside, ℓ − W − (that slack) is all a voxel needs to be told from deep inside.
  const double inner_band = std::max(2 * h, band + 0.5 * kSqrt3 * h + 2 * lookup_error + 2 * h - result.level);
  const detail::PartDistance part_distance(part, h, part_band_voxels * h, inner_band);
  if (!report_progress(request.progress, 0.1)) return result.cancelled = true, result;

  Eigen::AlignedBox3d box = swept_box(part, motion, times, safe_level + result.motion_error + band + 2 * h);
  if (request.clip) {
    Eigen::AlignedBox3d clip = *request.clip;
    clip.min().array() -= epsilon + 3 * h;
    clip.max().array() += epsilon + 3 * h;
    box = box.intersection(clip);
    if (box.isEmpty()) return result;
  }
  const Eigen::Vector3i lo = (box.min() / h).array().floor().cast<int>();
  const Eigen::Vector3i hi = (box.max() / h).array().ceil().cast<int>();
  result.grid_size = {hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z()};
  // The leaves over the box, and a ring of outside leaves around them: volumeToMesh looks for
  // sign changes from a leaf's voxels towards +x, +y, +z only, so a surface reaching the box's
  // faces (clipped) closes only against a leaf.
  std::vector<Coord> origins, ring;
  const auto leaf_floor = [](int v) { return v >= 0 ? v / kLeafDim * kLeafDim : -((-v + kLeafDim - 1) / kLeafDim) * kLeafDim; };
  const Eigen::Vector3i first(leaf_floor(lo.x()), leaf_floor(lo.y()), leaf_floor(lo.z()));
  const Eigen::Vector3i last(leaf_floor(hi.x()), leaf_floor(hi.y()), leaf_floor(hi.z()));
  for (int x = first.x() - kLeafDim; x <= last.x() + kLeafDim; x += kLeafDim)
    for (int y = first.y() - kLeafDim; y <= last.y() + kLeafDim; y += kLeafDim)
      for (int z = first.z() - kLeafDim; z <= last.z() + kLeafDim; z += kLeafDim) {
        const bool inner = x >= first.x() && x <= last.x() && y >= first.y() && y <= last.y() && z >= first.z() &&
                           z <= last.z();
        (inner ? origins : ring).emplace_back(x, y, z);
      }

  const std::vector<IndexMap> maps = index_maps(motion, times, h);
  const LeafEvaluator evaluator(part_distance, maps, sample_chunks(motion, times, 16), h, result.level, band, lookup_error);
  std::vector<LeafResult> leaves(origins.size());
  std::atomic<bool> cancelled{false};
  std::atomic<std::size_t> done{0};
  std::mutex progress_mutex;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, origins.size(), 16), [&](const tbb::blocked_range<std::size_t>& range) {
    if (cancelled) return;
    for (std::size_t n = range.begin(); n != range.end(); ++n) leaves[n] = evaluator.evaluate(origins[n]);
    const double fraction = double(done += range.size()) / double(origins.size());
    std::lock_guard lock(progress_mutex);
    if (!report_progress(request.progress, 0.1 + 0.8 * fraction)) cancelled = true;
  });
  if (cancelled) return result.cancelled = true, result;

  FloatGrid::Ptr swept = FloatGrid::create(float(band));
  swept->setTransform(openvdb::math::Transform::createLinearTransform(h));
  swept->setGridClass(openvdb::GRID_LEVEL_SET);
  FloatTree& tree = swept->tree();
  for (std::size_t n = 0; n < leaves.size(); ++n) {
    // Inside: a leaf of active −W voxels rather than a tile, so that the surface is also found
    // where the inside meets the background (volumeToMesh looks from active voxels only).
    if (leaves[n].kind == LeafResult::kInside) tree.addLeaf(new FloatTree::LeafNodeType(origins[n], float(-band), true));
    if (leaves[n].kind != LeafResult::kBand) continue;
    result.active_voxels += leaves[n].voxels;
    tree.addLeaf(leaves[n].leaf.release());
  }
  for (const Coord& origin : ring) tree.addLeaf(new FloatTree::LeafNodeType(origin, float(band), true));
  // The tight level, then up a ladder of levels while the clearance check fails, down to the
  // cell bound (conservative without a check). The grid stores G̃ − tight level.
  std::optional<Eigen::AlignedBox3d> region = request.clip;
  if (region) region->min().array() -= epsilon, region->max().array() += epsilon;
  const auto clear = [&](const geometry::Mesh& mesh) {
    return detail::mesh_keeps_clear(mesh, region, epsilon + delta,
                                    [&](const Eigen::Vector3d& x) { return evaluator.point_lower_bound(x); });
  };
  for (const double step : kLevelSteps) {
    const double level = std::min(safe_level, tight_level + step * h);
    result.mesh = contour(*swept, level - tight_level, result.filled_cavities);
    result.level = level;
    if (level == safe_level) break;
    if (!report_progress(request.progress, 0.9 + 0.02 * step)) return result.mesh = {}, result.cancelled = true, result;
    if ((result.verified = clear(result.mesh))) break;
  }
  result.margin = result.level - epsilon;
  if (!report_progress(request.progress, 1.0)) {
    result.mesh = {};
    result.cancelled = true;
  }
  return result;
}

}  // namespace reconfig::sweep
