#pragma once
/// @file
/// The line search of automatic resolution.

#include <functional>

namespace reconfig::resolve::detail {

/// The step s ∈ (0, reach] along a descent direction that lowers `energy(s)` most from
/// `e0` = energy(0), or 0 when none does. The energy along a line may have a barrier (e.g.
/// where a contained part's surface starts to cross the other's), so a halving scan from
/// `reach` first finds the best of 16 step lengths (down to reach/2¹⁵); golden-section search then refines it in
/// the bracket of its neighbours. Where the energy reaches 0 the answer is instead the smallest
/// zero step found by bisection, plus `clearance` when that still has zero energy.
double line_search(const std::function<double(double)>& energy, double e0, double reach, double clearance);

}  // namespace reconfig::resolve::detail
