#include "baked_tool_cache.h"

#include "reconfig/geometry/bounding_box.h"
#include "reconfig/geometry/mesh_check.h"

namespace reconfig::studio {

namespace {

/// Equal sizes and entries (Eigen's == alone requires equal sizes).
template <class Matrix>
bool same(const Matrix& a, const Matrix& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && a == b;
}

}  // namespace

bool BakedToolCache::same_as_last(const geometry::Mesh& part_mesh, const Eigen::Isometry3d& to_rest,
                                  double coating) const {
  return key_ && key_->coating == coating && key_->to_rest == to_rest.matrix() && same(key_->mesh.V, part_mesh.V) &&
         same(key_->mesh.F, part_mesh.F);
}

const BakedToolCache::Baked* BakedToolCache::bake(const geometry::Mesh& part_mesh, const Eigen::Isometry3d& to_rest,
                                                  double coating) {
  if (!same_as_last(part_mesh, to_rest, coating)) {
    ++bakes_;
    key_ = Key{part_mesh, to_rest.matrix(), coating};
    geometry::Mesh mesh = part_mesh;
    for (int v = 0; v < mesh.vertex_count(); ++v) mesh.V.row(v) = (to_rest * Eigen::Vector3d(mesh.V.row(v))).transpose();
    baked_.reset();
    if (geometry::check_mesh(mesh).is_closed()) {
      const Eigen::Vector3d center = geometry::bounding_box(mesh.V).center();
      sculpt::Tool tool = sculpt::Tool::baked(mesh, coating);
      baked_.emplace(Baked{std::move(mesh), center, std::move(tool)});
    }
  }
  return baked_ ? &*baked_ : nullptr;
}

}  // namespace reconfig::studio
