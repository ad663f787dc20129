#pragma once
/// @file
/// How a design asks for its collisions to be detected, saved with it (the scene file's
/// optional "collision" object), so that the studio and `reconfig check` agree on them after
/// it is reopened. Each setting left unset takes the detector's default.

#include <optional>
#include <string>

namespace reconfig::scene {

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

  bool empty() const {
    return !tolerance && !dop && !box_resolution && !frame && !conservative && !contact && !touching_collides;
  }
  /// These settings, each one replaced by `over`'s where that one is set.
  CollisionSettings overridden_by(const CollisionSettings& over) const;
  /// Why the settings cannot be used ("the tolerance must be a positive distance"), or "".
  std::string problem() const;
  bool operator==(const CollisionSettings&) const = default;
};

}  // namespace reconfig::scene
