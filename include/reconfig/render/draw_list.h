#pragma once
/// @file
/// What one frame shows: plain data handed to `Renderer::render` (immediate mode: build a new
/// list every frame). All coordinates are world coordinates (z up); colors are RGB in [0, 1].

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "reconfig/geometry/mesh.h"

namespace reconfig::render {

/// A triangle mesh, already posed. Opacity 1 draws it solid; below 1 it is blended after
/// everything solid (ghosts).
struct MeshItem {
  Eigen::MatrixX3d V;  ///< #V×3 posed positions
  Eigen::MatrixX3i F;  ///< #F×3 triangles
  /// Instead of V and F: rest geometry placed by `placement`. The renderer keeps such a mesh
  /// on the GPU for as long as the object lives, so a part that only moves costs no upload.
  std::shared_ptr<const geometry::Mesh> rest;
  Eigen::Isometry3d placement = Eigen::Isometry3d::Identity();
  /// The mesh is a closed, outward-oriented solid: its back faces can never be seen, so they
  /// are not drawn (half the triangles rasterized).
  bool cull_back_faces = false;
  Eigen::Vector3f color{0.7f, 0.7f, 0.7f};
  float opacity = 1.0f;
  bool highlighted = false;  ///< selection: tinted and outlined with a rim glow
};

/// A transparent axis-aligned box with opaque edges (collision interval boxes). Pulsating
/// boxes vary their opacity with `DrawList::seconds` (period 1 s). Boxes `on_top` show
/// through the parts (collision boxes lie inside them); parts still dim the hidden share.
struct BoxItem {
  Eigen::AlignedBox3d box;
  Eigen::Vector3f color{0.95f, 0.15f, 0.1f};
  float opacity = 0.35f;
  bool pulsate = true;
  bool on_top = true;
};

/// A polyline (a curve, a trajectory) or, with `strip = false`, independent segments
/// (points 0–1, 2–3, …). Drawn one pixel wide.
struct LineItem {
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector4f color{0.1f, 0.1f, 0.1f, 1.0f};
  bool strip = true;
};

/// An arrow from `from` to `to`: a line shaft and a shaded cone head.
struct ArrowItem {
  Eigen::Vector3d from = Eigen::Vector3d::Zero();
  Eigen::Vector3d to = Eigen::Vector3d::UnitX();
  Eigen::Vector3f color{0.1f, 0.3f, 0.9f};
  double head_fraction = 0.2;  ///< head length as a fraction of the arrow's length
};

/// A square grid of lines on the plane z = `height`, centered at (center.x, center.y), with
/// the x axis drawn red and the y axis green where they pass through the grid.
struct GridItem {
  bool visible = true;
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double height = 0;
  double spacing = 0.1;
  int half_lines = 10;  ///< lines on each side of the center, in each direction
  Eigen::Vector4f color{0.45f, 0.45f, 0.48f, 0.6f};
};

struct DrawList {
  std::vector<MeshItem> meshes;
  std::vector<BoxItem> boxes;
  std::vector<LineItem> lines;
  std::vector<ArrowItem> arrows;
  GridItem grid;
  Eigen::Vector3f background{0.96f, 0.96f, 0.97f};
  double seconds = 0;  ///< clock driving pulsating boxes
};

}  // namespace reconfig::render
