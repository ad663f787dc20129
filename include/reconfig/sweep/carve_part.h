#pragma once
/// @file
/// Carving a part by the motion of others (reconfigurables §6.7, eq. 4):
/// A ← A \ ∪_i offset(sweep(B_i, f_A⁻¹ ∘ f_{B_i}), ε).

#include <string>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/sweep/swept_volume.h"

namespace reconfig::sweep {

/// Carving's time steps: a quarter of a cell (δ <= h/4) instead of the sweep's half, so a cut
/// fits its carver within h (a rod pushed through a block leaves a channel rod + 2ε + 0.9·h
/// wide; at h/2 it would be 1.4·h), at about twice the time samples.
inline constexpr double kCarveTimeFraction = 0.25;

/// The sweep settings a carve starts from: the sweep's defaults with carving's time steps.
inline SweptVolumeRequest carve_sweep_defaults() {
  SweptVolumeRequest request;
  request.time_fraction = kCarveTimeFraction;
  return request;
}

struct CarveRequest {
  int transition = 0;          ///< index into scene.transitions
  int part = 0;                ///< A, the part carved (index into scene.parts)
  std::vector<int> carvers;    ///< the B_i, each != part
  double t0 = 0.0, t1 = 1.0;   ///< the time range of the transition whose motion carves
  /// Grid step, offset ε and time steps of every sweep (its `progress` is not used).
  SweptVolumeRequest sweep = carve_sweep_defaults();
  ProgressCallback progress;  ///< over all the sweeps and the subtraction; false cancels
};

struct CarveResult {
  /// A's new rest mesh; A's old one when refused or cancelled.
  geometry::Mesh mesh;
  /// Per carver, its swept volume offset by ε in A's rest frame.
  std::vector<SweptVolumeResult> sweeps;
  double volume_before = 0, volume_after = 0;  ///< of A's solid
  std::string problem;  ///< why the carve was refused (see `subtract_meshes`); empty if done
  bool cancelled = false;
  bool ok() const { return problem.empty() && !cancelled; }
};

/// The carvers' swept volumes, offset by ε, in A's rest frame and clipped to A's box: what
/// `carve_part` subtracts (one per carver, empty where a sweep misses A). Progress over all
/// of them; a cancelled sweep ends the list (its result says `cancelled`).
/// @param scene    a validated reconfigurable
/// @param request  what is carved, by what, when, and how finely
std::vector<SweptVolumeResult> carver_sweeps(const scene::Reconfigurable& scene, const CarveRequest& request);

/// Sweeps each carver in A's frame (`relative_motion`, `swept_volume`) and subtracts the
/// swept volumes from A exactly (`subtract_meshes`).
/// @param scene    a validated reconfigurable
/// @param request  what to carve, by what, when, and how finely
CarveResult carve_part(const scene::Reconfigurable& scene, const CarveRequest& request);

}  // namespace reconfig::sweep
