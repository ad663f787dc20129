#pragma once
/// @file
/// Turns a reconfigurable at one instant (or in one state) into a `DrawList`: its parts in
/// their colors, ghosts at other times, highlighted boxes, and a ground grid under it.

#include <Eigen/Geometry>
#include <vector>

#include "reconfig/render/draw_list.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/view/ghost_sampling.h"

namespace reconfig::render {

struct SceneDrawRequest {
  int transition = -1;  ///< pose at `time` of this transition, or
  double time = 0;
  int state = -1;       ///< (when transition < 0) pose in this state
  std::vector<int> selected;                  ///< part indices drawn highlighted
  std::vector<view::GhostSample> ghosts;      ///< times of `transition` drawn as ghosts
  float ghost_opacity = 0.3f;                 ///< opacity of a ghost of weight 1
  std::vector<Eigen::AlignedBox3d> boxes;     ///< e.g. collision interval boxes
  /// Parts drawn at these poses instead of their own at `time` (a drag in progress).
  std::vector<std::pair<int, motion::Pose>> pose_overrides;
  /// Optional, one per part: the parts' rest meshes as shared objects. Parts and ghosts are
  /// then drawn as these meshes plus a placement, which the renderer keeps on the GPU across
  /// frames (an editor's choice; the floor grid then lies under the posed bounding boxes).
  std::vector<std::shared_ptr<const geometry::Mesh>> resident_meshes;
  /// Optional, one per part: whether its mesh is a closed, outward-oriented solid (its back
  /// faces are then culled).
  std::vector<bool> solid_parts;
  bool grid = true;
};

/// Part colors: the part's own color, else a fixed palette by index.
Eigen::Vector3f part_color(const scene::Reconfigurable& scene, int part);

/// A nice grid spacing (1, 2 or 5 × 10^k) for a scene of that size: about a tenth of it.
double grid_spacing_for(double size);

/// The draw list of `request`. The grid lies under the lowest posed vertex (the floor),
/// centered under the scene, spacing from `grid_spacing_for` of the scene's extent.
/// @param scene a validated reconfigurable; request.transition / state must be valid indices
DrawList scene_draw_list(const scene::Reconfigurable& scene, const SceneDrawRequest& request);

}  // namespace reconfig::render
