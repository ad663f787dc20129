#pragma once
/// @file
/// How deep two placed parts are inside each other: the term that gives a descent direction
/// where the contour gives none (a part wholly inside another, faces overlapping face-on).

#include <Eigen/Geometry>

#include "reconfig/resolve/part_shape.h"
#include "reconfig/resolve/twist_gradient.h"

namespace reconfig::resolve {

struct Penetration {
  /// P = Σ_s w_s depth_s over the samples s of a inside b, plus the same for b's samples
  /// inside a: each part's area-weighted mean depth below the other's surface (a length; 0
  /// when neither part has a sample inside the other). A part wholly inside another at depth D
  /// everywhere gives D; lifting a box out of a face-on overlap lowers P steadily.
  double depth = 0;
  int samples_inside = 0;  ///< of both parts
  /// Samples in the other part's box whose winding number a ray counted
  /// (`geometry/ray_winding.h`): those against a closed, consistently oriented part.
  int ray_tests = 0;
  int distance_queries = 0;  ///< signed-distance queries made: samples inside, or not settled by a ray
  /// ∂P/∂(rigid motion of a), b held still (depth_s moves by −∇d·u(y) at a sample y of a, by
  /// +∇d·u(y) at a sample of b, where ∇d points from the sample to its nearest surface point).
  TwistGradient gradient;
};

/// The penetration term of part a placed by `place_a` and part b by `place_b`. Only samples
/// inside the other part's box are classified: against a closed, consistently oriented part, a
/// ray's winding count settles the samples outside it (winding number 0, exact where the count
/// is certain, and far cheaper than a nearest point for samples far from the surface); the
/// others get the part's signed distance (its sign: the pseudonormal's at the nearest point),
/// which also gives an inside sample's depth.
Penetration penetration(const PartShape& a, const Eigen::Isometry3d& place_a, const PartShape& b,
                        const Eigen::Isometry3d& place_b);

}  // namespace reconfig::resolve
