#pragma once
/// @file
/// Dragging the Bézier handles of the selected part's translation keys in the viewport (the
/// orange lines through each key on its path): which handle the mouse is over, and the key a
/// drag produces. Pure math (no GL, no ImGui), so it is tested directly.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "reconfig/motion/bezier_translation_track.h"
#include "reconfig/view/camera.h"
#include "reconfig/view/picking.h"

namespace reconfig::studio {

/// One handle of a translation key: `out` leaves the key towards the next one, `in` arrives
/// from the previous one.
struct HandleRef {
  int key = 0;
  bool out = true;
  bool operator==(const HandleRef&) const = default;
};

/// Where the end of a key's handle (`out` or in) is in the world: the part's pivot (rest
/// center) plus the handle.
Eigen::Vector3d handle_end(const motion::TranslationKey& key, const Eigen::Vector3d& pivot, bool out);

/// The handles that shape the motion: every key's, but the first key's `in` and the last
/// key's `out`.
std::vector<HandleRef> shaping_handles(const std::vector<motion::TranslationKey>& keys);

/// The shaping handle whose end is nearest the pixel `mouse`, within `tolerance` pixels.
std::optional<HandleRef> hit_handle(const std::vector<motion::TranslationKey>& keys, const Eigen::Vector3d& pivot,
                                    const view::Camera& camera, int width, int height, const Eigen::Vector2d& mouse,
                                    double tolerance = 7);

/// A drag in progress: the handle's end moves in the plane through where it was grabbed that
/// faces the camera, following the mouse ray.
struct HandleDrag {
  HandleRef handle;
  motion::TranslationKey start_key;
  Eigen::Vector3d start_end = Eigen::Vector3d::Zero();  ///< the handle's end when grabbed (world)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();    ///< of the drag plane: the camera's view direction
  view::Ray start_ray;

  /// The key with the handle moved by how far the ray's crossing of the plane moved since the
  /// start; the start key while the ray runs (nearly) parallel to the plane.
  motion::TranslationKey key_for(const view::Ray& ray) const;
};

}  // namespace reconfig::studio
