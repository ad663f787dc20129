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

struct CarveRequest {
  int transition = 0;          ///< index into scene.transitions
  int part = 0;                ///< A, the part carved (index into scene.parts)
  std::vector<int> carvers;    ///< the B_i, each != part
  double t0 = 0.0, t1 = 1.0;   ///< the time range of the transition whose motion carves
  /// Grid step, offset ε and time steps of every sweep (its `progress` is not used).
  SweptVolumeRequest sweep = {};
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
