#pragma once
/// @file
/// The last part baked as a sculpting tool, kept while nothing it was baked from changes.
///
/// Baking a part (placing its mesh in the sculpted part's rest frame, checking that it is
/// closed, building its signed-distance tree) costs time in the part's size; the sculpt mode
/// asks for the tool several times per frame. The cache rebakes only when the part's mesh, its
/// placement or the coating differ from the last bake, compared exactly. Not thread-safe (the
/// studio's UI thread owns it).

#include <Eigen/Geometry>

#include <optional>

#include "reconfig/geometry/mesh.h"
#include "reconfig/sculpt/tool.h"

namespace reconfig::studio {

class BakedToolCache {
 public:
  struct Baked {
    geometry::Mesh mesh;     ///< the part's mesh in the sculpted part's rest frame
    Eigen::Vector3d center;  ///< its box's center (the tool's origin, pivot of its rotation)
    sculpt::Tool tool;       ///< the baked tool, not yet turned by the settings' rotation
  };

  /// The tool baked from `part_mesh` mapped by `to_rest`, with `coating`; null when the mesh
  /// is not closed (it cannot be a tool). The pointer stays valid until the next call.
  const Baked* bake(const geometry::Mesh& part_mesh, const Eigen::Isometry3d& to_rest, double coating);

  int bakes() const { return bakes_; }  ///< how many times it baked (rather than reused)

 private:
  struct Key {
    geometry::Mesh mesh;
    Eigen::Matrix4d to_rest;
    double coating;
  };
  bool same_as_last(const geometry::Mesh& part_mesh, const Eigen::Isometry3d& to_rest, double coating) const;

  std::optional<Key> key_;
  std::optional<Baked> baked_;  ///< empty when the last bake found the mesh open
  int bakes_ = 0;
};

}  // namespace reconfig::studio
