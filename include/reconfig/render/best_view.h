#pragma once
/// @file
/// The view that shows a collision best (reconfigurables §4.3, Fig. 9): the camera aims at the
/// center of the collision's box X from the distance that keeps X in view from any side (up
/// +z); for two parts it looks along ±(rA × rB), orthogonal to both motions, whichever is less
/// occluded; for more parts, or when that is degenerate, it takes the best of many random
/// directions. "Best" is the most visible pixels of X, counted by `OcclusionCounter`, with the
/// other parts as occluders: X lies where the colliding parts cross, inside both of them, so
/// they would hide it from nearly every side.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/render/occlusion_counter.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/view/camera.h"

namespace reconfig::render {

/// One collision interval of one transition, and how to look for its view.
struct BestViewRequest {
  int transition = 0;
  double time = 0;          ///< the instant drawn (the interval's severity time)
  double t0 = 0, t1 = 0;    ///< the interval's extent, for the parts' motions
  std::vector<int> parts;   ///< the parts involved
  Eigen::AlignedBox3d box;  ///< X, the interval's box
  /// The design stands on a ground: a floor under its lowest point hides X from below, and
  /// sampling keeps to the northern hemisphere.
  bool ground = true;
  int samples = 1000;       ///< random directions when sampling (the six axis views are added)
  bool always_sample = false;  ///< sample even when ±(rA × rB) would do (two parts)
  std::uint64_t seed = 1;
  /// Occluders beyond this many triangles are simplified for the counts (display_simplification.h).
  int max_triangles = 4000;
  double fov_y = view::Camera{}.fov_y;
};

struct BestView {
  view::Camera camera;        ///< aspect 1; keep its direction and re-frame for other aspects
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< from X's center towards the eye
  OcclusionCount pixels;      ///< of X from `camera`, at the counter's resolution
  bool from_motion = false;   ///< chosen between ±(rA × rB), not by sampling
  int candidates = 0;         ///< views considered
  /// Of them, views counted with the occluders: the others cover fewer pixels of X than the
  /// chosen one shows, so they could not beat it.
  int counted = 0;
};

/// The request for `interval` of `transition` drawn at `time` (its severity time): its extent,
/// parts and box, the ground as `scene` has it, the rest as `BestViewRequest` says.
BestViewRequest interval_view_request(const scene::Reconfigurable& scene, int transition,
                                      const collision::CollisionInterval& interval, double time);

/// Poses every part but `request.parts` at `request.time` as occluders of `counter` and picks
/// the view of X.
/// Ties go to the first candidate (+(rA × rB), then the axis views, then the random ones);
/// when neither motion normal sees any of X the random directions are tried too. The answer is
/// that of counting every candidate, but a candidate in whose image X covers fewer pixels than
/// a counted one shows is not counted.
/// @param scene a validated reconfigurable; request.transition and parts valid indices
BestView best_view(OcclusionCounter& counter, const scene::Reconfigurable& scene, const BestViewRequest& request);

/// The triangles of the parts of `scene` but `excluded`, posed at time t of `transition`, that
/// come within `reach` of `center` (by their bounding boxes), as one soup (#V×3, #F×3); each
/// part's share simplified to its share of `max_triangles` when they are more.
void posed_occluders(const scene::Reconfigurable& scene, int transition, double t, const std::vector<int>& excluded,
                     int max_triangles, Eigen::MatrixX3d& V, Eigen::MatrixX3i& F,
                     const Eigen::Vector3d& center = Eigen::Vector3d::Zero(),
                     double reach = std::numeric_limits<double>::infinity());

}  // namespace reconfig::render
