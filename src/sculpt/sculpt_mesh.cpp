#include "reconfig/sculpt/sculpt_mesh.h"

#include <algorithm>
#include <utility>

namespace reconfig::sculpt {
namespace {

/// Room kept for growth, as a fraction of the rows in use.
constexpr double kRoom = 0.5;

/// Grows `storage` to hold at least `rows` rows, keeping the first `used` ones.
template <typename Matrix>
void reserve_rows(Matrix& storage, int used, int rows, bool room) {
  if (rows <= storage.rows()) return;
  const int capacity = room ? std::max(rows, static_cast<int>(rows * (1 + kRoom))) : rows;
  Matrix grown(capacity, 3);
  grown.topRows(used) = storage.topRows(used);
  storage = std::move(grown);
}

}  // namespace

SculptMesh::SculptMesh(geometry::Mesh mesh, Eigen::MatrixX3d normals, double cell)
    : vertices_(mesh.vertex_count()), faces_(mesh.face_count()), normals_(normals.rows() == mesh.V.rows()) {
  index_ = MeshIndex(mesh, cell);
  V_ = std::move(mesh.V);
  F_ = std::move(mesh.F);
  if (normals_) N_ = std::move(normals);
  reserve_rows(V_, vertices_, vertices_ + 1, true);
  reserve_rows(F_, faces_, faces_ + 1, true);
  if (normals_) reserve_rows(N_, vertices_, vertices_ + 1, true);
}

SculptMesh SculptMesh::adopt(geometry::Mesh&& mesh, Eigen::MatrixX3d&& normals, MeshIndex&& index) {
  SculptMesh out;
  out.vertices_ = mesh.vertex_count();
  out.faces_ = mesh.face_count();
  out.normals_ = normals.rows() == mesh.V.rows();
  out.room_ = false;
  if (index.vertex_count() != out.vertices_ || index.face_count() != out.faces_) index = MeshIndex(mesh, index.cell());
  out.index_ = std::move(index);
  out.V_ = std::move(mesh.V);
  out.F_ = std::move(mesh.F);
  if (out.normals_) out.N_ = std::move(normals);
  return out;
}

void SculptMesh::release(geometry::Mesh& mesh, Eigen::MatrixX3d& normals, MeshIndex& index) {
  if (V_.rows() != vertices_) V_.conservativeResize(vertices_, 3);
  if (F_.rows() != faces_) F_.conservativeResize(faces_, 3);
  mesh.V = std::move(V_);
  mesh.F = std::move(F_);
  if (normals_) {
    if (N_.rows() != vertices_) N_.conservativeResize(vertices_, 3);
    normals = std::move(N_);
  }
  index = std::move(index_);
  *this = SculptMesh();
}

void SculptMesh::resize(int vertices, int faces) {
  reserve_rows(V_, vertices_, vertices, room_);
  if (normals_) reserve_rows(N_, vertices_, vertices, room_);
  reserve_rows(F_, faces_, faces, room_);
  vertices_ = vertices;
  faces_ = faces;
}

void SculptMesh::assign(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const Eigen::MatrixX3d& N) {
  resize(static_cast<int>(V.rows()), static_cast<int>(F.rows()));
  this->V() = V;
  this->F() = F;
  if (normals_) this->N() = N;
}

void SculptMesh::reindex() { index_ = MeshIndex(V(), F(), index_.cell()); }

}  // namespace reconfig::sculpt
