#pragma once
/// @file
/// The ε-offset of the volume a moving part sweeps, as a closed triangle mesh contoured from a
/// conservative swept signed distance on a sparse grid (reconfigurables §6.7, eq. 5–6).

#include <Eigen/Geometry>

#include <optional>
#include <vector>

#include "reconfig/common/progress.h"
#include "reconfig/geometry/mesh.h"
#include "reconfig/sweep/relative_motion.h"

namespace reconfig::sweep {

struct SweptVolumeRequest {
  /// Grid step h (> 0), in scene units; 0 picks the longest side of the swept region's box / 128.
  double grid_step = 0;
  /// ε >= 0: the mesh bounds (at least) every point within ε of the swept volume.
  double offset = 0;
  /// No point of the part moves more than `time_fraction` · h between two time samples.
  double time_fraction = 0.5;
  /// Only the sweep inside this box (in the motion's target frame) is wanted, as when carving a
  /// part: the grid covers the box grown by 2h, and the mesh closes a little outside it.
  std::optional<Eigen::AlignedBox3d> clip = std::nullopt;
  /// Fraction in [0, 1]; return false to cancel (the result then says `cancelled`).
  ProgressCallback progress;
};

struct SweptVolumeResult {
  /// The contoured surface, closed and outward (empty when cancelled, when the part is empty or
  /// when the sweep misses `clip`).
  geometry::Mesh mesh;
  double grid_step = 0;   ///< h used
  int time_samples = 0;   ///< number of poses of the part sampled
  /// δ: the largest displacement of a point of the part between two samples (the motion bound).
  double motion_error = 0;
  /// The level contoured: ℓ = ε + δ + (√3/2)·h + √3·h (see `swept_volume`).
  double level = 0;
  /// ℓ − ε: how much farther than ε from the true swept volume the surface may lie, at most,
  /// plus a grid cell (the surface lies in cells whose corners straddle ℓ, so within ℓ + √3·h).
  double margin = 0;
  /// Cavities of the contoured volume (inward shells, pockets narrower than the grid resolves
  /// or real voids of the sweep) that were filled: the mesh is the outer shell only.
  int filled_cavities = 0;
  long long active_voxels = 0;  ///< voxels whose value was computed (the narrow band)
  std::vector<int> grid_size;   ///< cells of the box along x, y, z
  bool cancelled = false;
};

/// The swept volume S = ∪_t g(t)B offset by ε, meshed conservatively.
///
/// How. B's signed distance φ is computed once in B's frame on a grid of step h (exact distances
/// to the nearest triangle from the triangle tree up to a band, the sign from the parity of
/// surface crossings along the grid rows, not from pseudonormals) and looked up at the grid
/// points moved back by g(τ_k)⁻¹ at time samples τ_k chosen so that no point moves more
/// than δ between samples. The sparse grid of step h over S's box is evaluated leaf by leaf
/// (8³ voxels): a leaf is skipped for a sample whose value at the leaf's center proves every
/// voxel far outside, filled as an inside tile when one sample proves every voxel deep inside
/// (so the interior is labelled inside however far a step moves B: a single shell), and
/// otherwise evaluated voxel by voxel, F(x) = min_k φ(g(τ_k)⁻¹x), clamped to a band about ℓ.
/// The surface F = ℓ is extracted by OpenVDB `volumeToMesh` (no adaptivity), triangulated, and
/// its cavities are filled (which only adds volume: the result stays conservative).
///
/// The bound. Every point within ε of S lies within ε + δ of some sampled pose, so F <= ε + δ +
/// e there, e = (√3/2)·h the error of looking up φ at the nearest voxel; every corner of its
/// cell then has F <= ε + δ + e + √3·h = ℓ, and the surface only crosses cells whose corners
/// straddle ℓ, so the point is inside the mesh. Conversely every point of the mesh is within
/// ℓ + √3·h + e of S.
/// @param part     B in its rest frame: a closed, outward mesh (#V×3, #F×3)
/// @param motion   g(t) over the motion's time range
/// @param request  grid, offset, time steps, progress
SweptVolumeResult swept_volume(const geometry::Mesh& part, const RelativeMotion& motion,
                               const SweptVolumeRequest& request = {});

}  // namespace reconfig::sweep
