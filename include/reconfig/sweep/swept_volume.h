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
  /// No point of the part moves more than `time_fraction` · h between two time samples (δ).
  /// Carving uses a quarter (carve_part.h: `kCarveTimeFraction`) for a tighter cut.
  double time_fraction = 0.5;
  /// Only the sweep inside this box (in the motion's target frame) is wanted, as when carving a
  /// part: the grid covers the box grown by ε + 3h, and the mesh closes a little outside it
  /// (the bound below then holds for the points of the box).
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
  /// The level ℓ of G̃ contoured: max(ε + δ + 0.15·h, √3·h + δ) when `verified`, else ε + δ + √3·h
  /// (see `swept_volume`).
  double level = 0;
  /// ℓ − ε: how much farther than ε from the true swept volume the surface may lie, at most,
  /// plus the contour's own error (a flat wall lies at ℓ exactly).
  double margin = 0;
  /// Whether the tight level passed the clearance check; otherwise the mesh is the cell-bound
  /// contour (conservative by construction, about 1.5 cells wider on each side).
  bool verified = false;
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
/// surface crossings along the grid rows, not from pseudonormals). At time samples τ_k, chosen
/// so that no point of B moves more than δ <= `time_fraction`·h between two, the distance to
/// pose k at a point x is bounded from below by D̃_k(x), read from B's grid at g(τ_k)⁻¹x
/// (`PartDistance::lower_bound`: the trilinear interpolant of D² minus its variance, exact at
/// the grid points, nearly so on walls), and G̃ = min_k D̃_k <= G_s = the distance to the union
/// of the sampled poses. The sparse grid of step h over S's box is evaluated leaf by leaf (8³
/// voxels): a leaf is skipped for a sample whose value at the leaf's center proves every voxel
/// far outside, filled as an inside tile when one sample proves every voxel deep inside (so the
/// interior is labelled inside however far a step moves B: a single shell), and otherwise
/// evaluated voxel by voxel, clamped to a band W = 2h about ℓ. The surface G̃ = ℓ is extracted by
/// OpenVDB `volumeToMesh` (no adaptivity), triangulated, and its cavities are filled (which only
/// adds volume).
///
/// The bound. G the distance to S: every point x has G(x) >= G_s(x) − δ (each point of a pose
/// at time t lies within δ of the same point at a sample), and G_s >= G̃. No margin is needed for
/// the distance look-ups: G̃ is a lower bound, not an estimate.
/// 1. Tight level ℓ = max(ε + δ + 0.15·h, √3·h + δ), then checked (`mesh_keeps_clear`): every point
///    q of every triangle (that may meet the clip box grown by ε) has G_s(q) > ε + δ, from lower
///    bounds at its corners and the concavity of G_s² − |x|², so the surface misses the ε-offset
///    {G <= ε}. Every point s of S lies inside the mesh: the corners c of its cell have
///    G̃(c) <= G_s(c) <= √3·h + δ < ℓ, and a cell whose corners all lie below ℓ is not crossed by
///    the surface (`volumeToMesh` puts it in sign-changing cells only). The segment from a point
///    p of the ε-offset to its nearest point on S stays in the offset, so it never crosses the
///    surface either: p is inside. On a flat wall the mesh lies at ℓ, ε + δ + 0.15·h from S.
/// 2. If the check fails (a corner or a curved part of the sweep the chords cut into), the levels
///    ℓ + h/4 and ℓ + 0.6·h are tried the same way, and finally ℓ = ε + δ + √3·h, conservative by
///    the cell argument alone: a point p with G(p) <= ε has
///    G_s <= ε + δ + √3·h = ℓ at every corner of its cell, so its cell is inside.
/// Conversely every point of the mesh lies within ℓ + √3·h of the sampled poses.
/// @param part     B in its rest frame: a closed, outward mesh (#V×3, #F×3)
/// @param motion   g(t) over the motion's time range
/// @param request  grid, offset, time steps, progress
SweptVolumeResult swept_volume(const geometry::Mesh& part, const RelativeMotion& motion,
                               const SweptVolumeRequest& request = {});

}  // namespace reconfig::sweep
