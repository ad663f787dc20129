#pragma once
/// @file
/// How a design asks for its collisions to be detected, saved with it (the scene file's
/// optional "collision" object), so that the studio and `reconfig check` agree on them after
/// it is reopened. Each setting left unset takes the detector's default.

#include <array>
#include <optional>
#include <string>

namespace reconfig::scene {

/// The half-space counts a k-DOP family may have ("dop" in scene files, `--dop`): the one list
/// of the families, which `collision::kDopFamilies` follows (checked where they meet).
inline constexpr std::array<int, 3> kDopHalfspaces = {8, 28, 80};

/// Whether `halfspaces` is one of `kDopHalfspaces`.
constexpr bool is_dop_halfspace_count(int halfspaces) {
  for (const int h : kDopHalfspaces)
    if (h == halfspaces) return true;
  return false;
}

/// The counts as a user reads them: "8, 28 or 80".
std::string dop_halfspace_choices();

/// (The members' explicit initializers let `{.dop = 8}` leave the others unset without a
/// -Wmissing-field-initializers warning.)
struct CollisionSettings {
  /// Largest distance between the sampled and the true motion, in scene units (> 0).
  std::optional<double> tolerance = std::nullopt;
  /// The k-DOP family of the spacetime hierarchies: 8, 28 or 80 half-spaces.
  std::optional<int> dop = std::nullopt;
  /// Grid of the collision boxes, a fraction of the smaller part's size, in [0, 1] (0: exact).
  std::optional<double> box_resolution = std::nullopt;
  /// Length of a frame, a fraction of a transition, in (0, 1].
  std::optional<double> frame = std::nullopt;
  /// Also report near misses that the true motion may turn into collisions.
  std::optional<bool> conservative = std::nullopt;
  /// The contact tolerance δ, in scene units (> 0): parts that meet by no more than δ only
  /// touch. Unset: 1e-6 of the design's size.
  std::optional<double> contact = std::nullopt;
  /// Whether touching counts as a collision too.
  std::optional<bool> touching_collides = std::nullopt;
  /// The clearance, in scene units (≥ 0): parts that come closer than this without colliding
  /// are reported as clearance intervals. Unset or 0: no clearance check.
  std::optional<double> clearance = std::nullopt;

  bool empty() const {
    return !tolerance && !dop && !box_resolution && !frame && !conservative && !contact && !touching_collides &&
           !clearance;
  }
  /// These settings, each one replaced by `over`'s where that one is set.
  CollisionSettings overridden_by(const CollisionSettings& over) const;
  /// Why the settings cannot be used ("the tolerance must be a positive distance"), or "".
  std::string problem() const;
  bool operator==(const CollisionSettings&) const = default;
};

}  // namespace reconfig::scene
