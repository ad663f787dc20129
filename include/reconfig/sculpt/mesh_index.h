#pragma once
/// @file
/// The spatial index a mesh keeps while it is sculpted (Sweepers §5.1: only what a tool's box
/// holds is touched): its vertices bucketed in a dense uniform grid over the mesh's box (and
/// a margin; vertices beyond it go to the border cells), and the faces around each vertex.
/// Strokes (`sculpt_mesh`) keep it up to date as they move, add and remove vertices.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

#include "reconfig/geometry/mesh.h"

namespace reconfig::sculpt {

class MeshIndex {
 public:
  MeshIndex() = default;
  /// Indexes `mesh`. @param cell  the grid's cell edge (> 0), or 0: eight mean edge lengths
  explicit MeshIndex(const geometry::Mesh& mesh, double cell = 0) : MeshIndex(mesh.V, mesh.F, cell) {}
  /// Indexes the mesh of #V×3 positions V and #F×3 faces F (as the constructor above).
  MeshIndex(const Eigen::Ref<const Eigen::MatrixX3d>& V, const Eigen::Ref<const Eigen::MatrixX3i>& F, double cell = 0);

  /// The vertices of V inside `box` (closed), in ascending order — those a scan of every
  /// vertex would find. @param V  #V×3, the positions the index was kept up to date with
  std::vector<int> vertices_in(const Eigen::AlignedBox3d& box, const Eigen::Ref<const Eigen::MatrixX3d>& V) const;
  /// The faces that use vertex v (in no particular order).
  const std::vector<int>& faces_of(int v) const { return vertex_faces_[v]; }

  /// Vertex v moved from `from` to `to`.
  void move_vertex(int v, const Eigen::Vector3d& from, const Eigen::Vector3d& to);
  /// A new vertex (numbered `vertex_count()`) at p, used by no face yet.
  void add_vertex(const Eigen::Vector3d& p);
  /// Face f's corners changed from `before` to `after`; a new face f (= the face count so far)
  /// has `before` = {−1, −1, −1}.
  void change_face(int f, const std::array<int, 3>& before, const std::array<int, 3>& after);

  int vertex_count() const { return static_cast<int>(vertex_faces_.size()); }
  int face_count() const { return faces_; }
  double cell() const { return cell_; }

 private:
  /// The cell holding p (clamped to the grid), as its three coordinates.
  std::array<int, 3> cell_of(const Eigen::Vector3d& p) const;
  int cell_number(const std::array<int, 3>& c) const { return (c[0] * dims_[1] + c[1]) * dims_[2] + c[2]; }

  double cell_ = 1;     ///< the cell edge asked for
  double inverse_ = 1;  ///< 1 / the grid's cell edge (≥ `cell_`: the grid's size is bounded)
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  ///< the grid's low corner
  std::array<int, 3> dims_{1, 1, 1};                  ///< cells along each axis
  std::vector<std::vector<int>> cells_ = std::vector<std::vector<int>>(1);  ///< vertices by cell
  std::vector<std::vector<int>> vertex_faces_;
  int faces_ = 0;
};

}  // namespace reconfig::sculpt
