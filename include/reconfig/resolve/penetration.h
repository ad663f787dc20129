#pragma once
/// @file
/// How deep two placed parts are inside each other: the term that gives a descent direction
/// where the contour gives none (a part wholly inside another, faces overlapping face-on).

#include <Eigen/Geometry>

#include <array>
#include <limits>
#include <span>
#include <vector>

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
  int distance_queries = 0;  ///< signed-distance queries made (memos of nearby poses save some)
  /// ∂P/∂(rigid motion of a), b held still (depth_s moves by −∇d·u(y) at a sample y of a, by
  /// +∇d·u(y) at a sample of b, where ∇d points from the sample to its nearest surface point).
  TwistGradient gradient;
};

/// What one evaluation of the penetration term learned about each sample, for evaluations of
/// the same two parts at nearby poses. The signed distance to a closed mesh changes by at most
/// as much as the point moves (it is 1-Lipschitz), so a sample known to lie outside by more
/// than it has moved since needs no query, and one that may lie inside is searched only as
/// far as it can be from the surface.
struct PenetrationMemo {
  struct Sample {
    /// Where the sample was, in the other part's rest frame (NaN: nothing known).
    Eigen::Vector3d position = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    double lower = 0;  ///< signed distance there ≥ lower
    double upper_abs = std::numeric_limits<double>::infinity();  ///< |signed distance| ≤ this
  };
  /// [0]: a's samples in b's frame; [1]: b's samples in a's frame (PartShape::sample_points).
  std::array<std::vector<Sample>, 2> samples;
};

/// The penetration term of part a placed by `place_a` and part b by `place_b`. Samples are
/// classified with each part's signed distance (exact sign on closed meshes); only samples
/// inside the other part's box are queried.
///
/// @param earlier  memos of evaluations of the same a and b at other poses: they only save
///                 queries, the result is the same (bit for bit) with or without them. They
///                 are used against closed meshes only (every edge with two faces), where the
///                 sign is Lipschitz too.
/// @param record   when given, filled with what this evaluation learned
Penetration penetration(const PartShape& a, const Eigen::Isometry3d& place_a, const PartShape& b,
                        const Eigen::Isometry3d& place_b, std::span<const PenetrationMemo* const> earlier = {},
                        PenetrationMemo* record = nullptr);

}  // namespace reconfig::resolve
