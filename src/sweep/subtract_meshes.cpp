// The only file of the sweep module that includes CGAL (its headers are heavy).
#include "reconfig/sweep/subtract_meshes.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include <fmt/format.h>

#include "reconfig/geometry/mesh_check.h"

namespace reconfig::sweep {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

SurfaceMesh to_surface_mesh(const geometry::Mesh& mesh) {
  SurfaceMesh out;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  vertices.reserve(mesh.V.rows());
  for (int v = 0; v < mesh.vertex_count(); ++v)
    vertices.push_back(out.add_vertex(Kernel::Point_3(mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2))));
  for (int f = 0; f < mesh.face_count(); ++f) out.add_face(vertices[mesh.F(f, 0)], vertices[mesh.F(f, 1)], vertices[mesh.F(f, 2)]);
  return out;
}

geometry::Mesh to_mesh(const SurfaceMesh& mesh) {
  geometry::Mesh out;
  out.V.resize(mesh.number_of_vertices(), 3);
  std::vector<int> index(mesh.num_vertices(), -1);
  int next = 0;
  for (const auto v : mesh.vertices()) {
    const Kernel::Point_3& p = mesh.point(v);
    out.V.row(next) << CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z());
    index[v.idx()] = next++;
  }
  out.F.resize(mesh.number_of_faces(), 3);
  int f = 0;
  for (const auto face : mesh.faces()) {
    int c = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(face), mesh)) out.F(f, c++) = index[v.idx()];
    ++f;
  }
  return out;
}

/// Empty if `mesh` is a valid solid, else what is wrong with it.
std::string solid_problem(const geometry::Mesh& mesh) {
  geometry::MeshCheckOptions options;
  options.max_self_intersection_pairs = 0;  // whether there is any is enough
  const geometry::MeshReport report = geometry::check_mesh(mesh, options);
  return report.is_valid_solid() ? std::string() : report.summary();
}

}  // namespace

SubtractionResult subtract_meshes(const geometry::Mesh& solid, const std::vector<geometry::Mesh>& cutters,
                                  const ProgressCallback& progress) {
  SubtractionResult result;
  result.mesh = solid;
  if (std::string problem = solid_problem(solid); !problem.empty()) return result.problem = "the carved part: " + problem, result;
  for (std::size_t c = 0; c < cutters.size(); ++c)
    if (std::string problem = solid_problem(cutters[c]); !problem.empty())
      return result.problem = fmt::format("cutter {}: {}", c + 1, problem), result;
  SurfaceMesh carved = to_surface_mesh(solid);
  for (std::size_t c = 0; c < cutters.size(); ++c) {
    if (!report_progress(progress, double(c) / double(cutters.size()))) return result.cancelled = true, result;
    SurfaceMesh cutter = to_surface_mesh(cutters[c]);
    SurfaceMesh difference;
    if (!PMP::corefine_and_compute_difference(carved, cutter, difference))
      return result.problem = fmt::format("cutter {}: the exact difference is not a solid (CGAL corefinement)", c + 1),
             result;
    carved = std::move(difference);
  }
  geometry::Mesh mesh = to_mesh(carved);
  if (mesh.empty()) return result.problem = "nothing is left of the carved part", result;
  if (std::string problem = solid_problem(mesh); !problem.empty())
    return result.problem = "the carved result rounded to double: " + problem, result;
  result.mesh = std::move(mesh);
  report_progress(progress, 1.0);
  return result;
}

}  // namespace reconfig::sweep
