#include "reconfig/render/best_view.h"

#include <algorithm>

#include "reconfig/geometry/display_simplification.h"
#include "reconfig/view/box_view_camera.h"
#include "reconfig/view/scene_bounds.h"
#include "reconfig/view/view_candidates.h"

namespace reconfig::render {
namespace {

struct Choice {
  int index = -1;
  OcclusionCount pixels;
};

// The candidate with the most visible pixels (the first of equals).
Choice most_visible(const std::vector<OcclusionCount>& counts) {
  Choice best;
  for (std::size_t i = 0; i < counts.size(); ++i)
    if (best.index < 0 || counts[i].visible > best.pixels.visible) best = {static_cast<int>(i), counts[i]};
  return best;
}

}  // namespace

void posed_occluders(const scene::Reconfigurable& scene, int transition, double t, const std::vector<int>& excluded,
                     int max_triangles, Eigen::MatrixX3d& V, Eigen::MatrixX3i& F) {
  std::vector<bool> occludes(scene.parts.size(), true);
  for (int p : excluded) occludes[p] = false;
  long triangles = 0;
  for (std::size_t p = 0; p < scene.parts.size(); ++p)
    if (occludes[p]) triangles += scene.parts[p].mesh.F.rows();
  const bool simplify = triangles > max_triangles;
  std::vector<Eigen::MatrixX3d> vertices;
  std::vector<Eigen::MatrixX3i> faces;
  long total_vertices = 0, total_faces = 0;
  for (std::size_t p = 0; p < scene.parts.size(); ++p) {
    if (!occludes[p]) continue;
    const scene::Part& part = scene.parts[p];
    geometry::Mesh simplified;
    if (simplify) {
      const double share = static_cast<double>(part.mesh.F.rows()) / static_cast<double>(triangles);
      simplified = geometry::simplify_for_display(part.mesh, std::max(4, static_cast<int>(share * max_triangles)));
    }
    const geometry::Mesh& mesh = simplify ? simplified : part.mesh;
    const Eigen::Isometry3d M = scene.pose_at(transition, static_cast<int>(p), t).to_isometry(part.center);
    vertices.push_back((mesh.V * M.linear().transpose()).rowwise() + M.translation().transpose());
    faces.push_back(mesh.F);
    total_vertices += vertices.back().rows();
    total_faces += faces.back().rows();
  }
  V.resize(total_vertices, 3);
  F.resize(total_faces, 3);
  long v = 0, f = 0;
  for (std::size_t p = 0; p < vertices.size(); ++p) {
    V.middleRows(v, vertices[p].rows()) = vertices[p];
    F.middleRows(f, faces[p].rows()) = faces[p].array() + static_cast<int>(v);
    v += vertices[p].rows();
    f += faces[p].rows();
  }
}

BestView best_view(OcclusionCounter& counter, const scene::Reconfigurable& scene, const BestViewRequest& request) {
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  posed_occluders(scene, request.transition, request.time, request.parts, request.max_triangles, V, F);
  counter.set_occluders(V, F);
  // A box that is a point or a sliver still gets a view of some of its surroundings.
  const Eigen::AlignedBox3d bounds = view::scene_bounds_at(scene, request.transition, request.time);
  const double min_radius = 0.02 * (bounds.isEmpty() ? 1.0 : bounds.diagonal().norm());

  const auto count_directions = [&](const std::vector<Eigen::Vector3d>& directions) {
    std::vector<view::Camera> cameras;
    cameras.reserve(directions.size());
    for (const Eigen::Vector3d& d : directions)
      cameras.push_back(view::box_view_camera(request.box, d, 1.0, request.fov_y, min_radius));
    return std::pair{cameras, counter.count(request.box, cameras)};
  };
  const auto result = [&](const std::vector<Eigen::Vector3d>& directions, bool from_motion) {
    const auto [cameras, counts] = count_directions(directions);
    const Choice best = most_visible(counts);
    return BestView{cameras[best.index], directions[best.index], best.pixels, from_motion,
                    static_cast<int>(directions.size())};
  };

  if (request.parts.size() == 2) {
    const int a = request.parts[0], b = request.parts[1];
    const auto normals =
        view::motion_normal_directions(view::part_displacement(scene, request.transition, a, request.t0, request.t1),
                                       view::part_displacement(scene, request.transition, b, request.t0, request.t1));
    if (normals) {
      BestView chosen = result({(*normals)[0], (*normals)[1]}, true);
      if (chosen.pixels.visible > 0) return chosen;
    }
  }
  std::vector<Eigen::Vector3d> directions = view::axis_view_directions(request.ground);
  const std::vector<Eigen::Vector3d> random = view::random_view_directions(request.samples, request.ground, request.seed);
  directions.insert(directions.end(), random.begin(), random.end());
  return result(directions, false);
}

}  // namespace reconfig::render
