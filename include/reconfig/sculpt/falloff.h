#pragma once
/// @file
/// The C² falloff μ of a sweeper tool: 1 inside the tool, 0 beyond its coating (Sweepers §3.1).

namespace reconfig::sculpt {

/// The steepest slope of the falloff over a coating of thickness 1: min μ'(d) = −1.875 / λ,
/// reached halfway through the coating. The foldover bounds on the number of sub-steps use it.
inline constexpr double kFalloffSteepestSlope = 1.875;

/// μ(d) = 1 for d ≤ 0, 1 + x³(x(15 − 6x) − 10) with x = d/λ for 0 < d < λ, 0 for d ≥ λ: a
/// piecewise polynomial, C² everywhere (its first and second derivatives vanish at 0 and λ).
/// @param d        distance to the tool (≤ 0 inside)
/// @param coating  coating thickness λ (> 0)
inline double falloff(double d, double coating) {
  if (d <= 0) return 1;
  if (d >= coating) return 0;
  const double x = d / coating;
  return 1 + x * x * x * (x * (15 - 6 * x) - 10);
}

/// dμ/dd = −30 x²(1 − x)² / λ inside the coating, 0 elsewhere (never below −1.875 / λ).
/// @param d        distance to the tool
/// @param coating  coating thickness λ (> 0)
inline double falloff_slope(double d, double coating) {
  if (d <= 0 || d >= coating) return 0;
  const double x = d / coating, y = 1 - x;
  return -30 * x * x * y * y / coating;
}

}  // namespace reconfig::sculpt
