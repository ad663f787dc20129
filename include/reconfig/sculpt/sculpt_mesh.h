#pragma once
/// @file
/// The mesh a drag sculpts from frame to frame: vertices, normals and faces stored with room
/// to grow (remeshing appends rows every frame; reallocating and copying whole #V×3 matrices
/// each time cost more than the rest of a frame), and the spatial index that follows them.

#include <Eigen/Core>

#include "reconfig/geometry/mesh.h"
#include "reconfig/sculpt/mesh_index.h"

namespace reconfig::sculpt {

class SculptMesh {
 public:
  template <typename Matrix>
  using Rows = Eigen::Block<Matrix, Eigen::Dynamic, 3>;  ///< the first rows of a #rows×3 matrix

  SculptMesh() = default;
  /// Takes `mesh` and its `normals` (#V×3, or empty: none kept), indexes them (`MeshIndex` of
  /// that cell, 0: its default) and keeps room to grow by half again before reallocating.
  SculptMesh(geometry::Mesh mesh, Eigen::MatrixX3d normals, double cell = 0);
  /// Takes over `mesh`, `normals` and `index` (of that mesh: rebuilt if its counts differ)
  /// without copying them, and grows no more than needed: what a one-off stroke on a
  /// `geometry::Mesh` uses before `release` gives them back.
  static SculptMesh adopt(geometry::Mesh&& mesh, Eigen::MatrixX3d&& normals, MeshIndex&& index);
  /// Gives the mesh, its normals and its index back (this mesh is left empty).
  void release(geometry::Mesh& mesh, Eigen::MatrixX3d& normals, MeshIndex& index);

  int vertex_count() const { return vertices_; }
  int face_count() const { return faces_; }
  bool has_normals() const { return normals_; }

  /// #V×3 positions, #V×3 unit normals (0 rows if none are kept) and #F×3 faces: views of the
  /// first rows of the storage, valid until the next `resize`.
  Rows<const Eigen::MatrixX3d> V() const { return V_.topRows(vertices_); }
  Rows<Eigen::MatrixX3d> V() { return V_.topRows(vertices_); }
  Rows<const Eigen::MatrixX3d> N() const { return N_.topRows(normals_ ? vertices_ : 0); }
  Rows<Eigen::MatrixX3d> N() { return N_.topRows(normals_ ? vertices_ : 0); }
  Rows<const Eigen::MatrixX3i> F() const { return F_.topRows(faces_); }
  Rows<Eigen::MatrixX3i> F() { return F_.topRows(faces_); }

  /// Keeps the first `vertices` and `faces` rows (new rows uninitialized); reallocates only
  /// when the room kept is used up. The index is not told: keep it up to date, or `reindex`.
  void resize(int vertices, int faces);
  /// Replaces the vertices, normals (ignored if none are kept) and faces by copies of these;
  /// the index is not told.
  void assign(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const Eigen::MatrixX3d& N);

  const MeshIndex& index() const { return index_; }
  MeshIndex& index() { return index_; }
  /// Indexes the mesh anew (same cell).
  void reindex();

  /// A copy as a `geometry::Mesh`, and of the normals.
  geometry::Mesh mesh() const { return {V(), F()}; }
  Eigen::MatrixX3d normals() const { return N(); }

 private:
  Eigen::MatrixX3d V_, N_;  ///< capacity rows, the first `vertices_` used
  Eigen::MatrixX3i F_;      ///< capacity rows, the first `faces_` used
  int vertices_ = 0, faces_ = 0;
  bool normals_ = false;
  bool room_ = true;  ///< grow by half again (false: exactly as needed)
  MeshIndex index_;
};

}  // namespace reconfig::sculpt
