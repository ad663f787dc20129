#pragma once
/// @file
/// Touching versus interference of two triangles of two parts: the contact semantics shared by
/// the spacetime engine and the reference check.
///
/// Two intersecting triangles X (of one part) and Y (of the other), each wound so that its
/// normal points out of its part, only *touch* within δ when some unit direction u separates
/// them up to δ:
///
///     max_{x ∈ X} u·x − min_{y ∈ Y} u·y ≤ δ
///
/// (X lies below Y along u, reaching at most δ above Y's lowest point), and each of them that
/// lies flat in the separating band (its extent along u at most 2δ) faces the right way:
/// X's outward normal does not point down (u·n_X ≥ −η |n_X|), Y's does not point up
/// (u·n_Y ≤ η |n_Y|), η = 1e-9 absorbing the rounding of the normals. Otherwise they
/// *interfere*. So faces touching face to face (a box on a table, a drawer in its runner), an
/// edge or a vertex resting on a face, and flush side faces of a stack (coplanar, facing the same
/// way, sharing an edge) touch, at any orientation and with rounding in every coordinate;
/// coplanar faces facing the same way that overlap by more than δ in their plane (the sides of
/// two boxes pressed into each other), a flat face lying inside the other part's half-space, and
/// faces crossing by more than δ interfere. The directions tried are those of the separating axis
/// theorem for two triangles: the two normals, the nine cross products of their edges and the
/// six in-plane normals of their edges — "touch" is certified, anything not certified counts as
/// interference (never a missed one).

#include <Eigen/Core>
#include <array>
#include <vector>

#include "reconfig/collision/triangle_pair_ccd.h"
#include "reconfig/geometry/triangle_corners.h"

namespace reconfig::collision {

using geometry::TriangleCorners;

/// Whether triangles a and b (which the caller knows to intersect, or to come near) only touch
/// within `delta` (the definition above).
bool triangles_touch(const TriangleCorners& a, const TriangleCorners& b, double delta);

/// Whether triangles whose vertices move linearly from a0, b0 (step parameter 0) to a1, b1 (1)
/// only touch within `delta` at every time of [lo, hi] ⊂ [0, 1]: one fixed direction, tried at
/// the middle time, separates them up to δ at both ends (the overlap along a fixed direction is
/// convex in time); a triangle not certified thick along it throughout faces the right way
/// throughout (checked on its normal's exact quadratic in time).
bool touching_throughout(const TriangleCorners& a0, const TriangleCorners& a1, const TriangleCorners& b0,
                         const TriangleCorners& b1, double lo, double hi, double delta);

/// The parts of the pieces (step parameters, sorted, as `triangle_pair_ccd` reports them) where
/// the moving triangles may interfere beyond `delta`: each piece is halved, down to 1/2^depth of
/// its length, wherever `touching_throughout` cannot certify it; what is left is kept.
/// Sorted; touching parts of one piece stay separate intervals sharing an end.
std::vector<TimeInterval> interference_pieces(const TriangleCorners& a0, const TriangleCorners& a1,
                                              const TriangleCorners& b0, const TriangleCorners& b1,
                                              const std::vector<TimeInterval>& pieces, double delta, int depth = 5);

}  // namespace reconfig::collision
