#pragma once
/// @file
/// How much of a box shows from many cameras at once (reconfigurables §4.3): the occluders'
/// depth is rendered once per camera, then the box, opaque, marking the pixels where it passes
/// the depth test, and the marks are counted. The cameras are batched: each one draws into its
/// own small tile of one atlas, all of them in one instanced draw of the occluders, clipped to
/// the rectangle the box covers in that camera and to the box's far side (nothing else can hide
/// it); then all of their boxes in one draw, and one read-back of the marks. The count is the
/// one an occlusion query (`GL_SAMPLES_PASSED`) of each box would give: front faces only, no
/// multisampling, so each pixel is marked once.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "reconfig/view/camera.h"

namespace reconfig::render {

/// Pixels of the box in one camera's square image.
struct OcclusionCount {
  long visible = 0;  ///< not hidden by an occluder (faces lying on an occluder's surface count)
  long total = 0;    ///< covered by the box were nothing in front of it
  double visible_fraction() const { return total > 0 ? static_cast<double>(visible) / total : 0.0; }
};

/// Needs a current OpenGL 3.3 core context (e.g. `EglContext`) for its whole life, on the
/// thread that created it. `count` and `coverage` give back the framebuffer binding, viewport,
/// pack alignment and clear color they found;
/// the other state it touches (depth, culling, blending) the renderer sets for itself.
class OcclusionCounter {
 public:
  /// `resolution` × `resolution` pixels per camera (≥ 8).
  explicit OcclusionCounter(int resolution = 64);
  ~OcclusionCounter();
  OcclusionCounter(const OcclusionCounter&) = delete;
  OcclusionCounter& operator=(const OcclusionCounter&) = delete;

  /// The triangles that may hide the box, in world coordinates: #V×3 positions, #F×3 indices.
  /// Both sides of each triangle occlude (a camera inside a part sees nothing).
  void set_occluders(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

  /// For each camera (drawn with aspect 1 at `resolution()` pixels a side), the pixels of `box`;
  /// without `totals` only the visible ones (`total` stays 0).
  std::vector<OcclusionCount> count(const Eigen::AlignedBox3d& box, const std::vector<view::Camera>& cameras,
                                    bool totals = true);

  /// What `count(box, cameras, totals)` gives for cameras[i], for each i of `which` (valid
  /// indices), in that order, exactly: each camera is drawn where it would be there (the tile of
  /// index i modulo `batch_size()`), and a pixel whose center lies on an edge may count
  /// differently in another tile, by rounding.
  std::vector<OcclusionCount> count_selected(const Eigen::AlignedBox3d& box, const std::vector<view::Camera>& cameras,
                                             const std::vector<int>& which, bool totals = true);

  /// For each camera the pixels `box` covers, nothing hiding it: the `total` of `count`, an
  /// upper bound of `visible`, at the price of drawing the boxes alone.
  std::vector<long> coverage(const Eigen::AlignedBox3d& box, const std::vector<view::Camera>& cameras);

  int resolution() const;
  /// Cameras drawn per batch (tiles in the atlas).
  int batch_size() const;

 private:
  std::vector<OcclusionCount> count_pixels(const Eigen::AlignedBox3d& box, const std::vector<view::Camera>& cameras,
                                           const std::vector<int>& which, bool visible, bool totals);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace reconfig::render
