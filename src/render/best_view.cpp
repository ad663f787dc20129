#include "reconfig/render/best_view.h"

#include <algorithm>
#include <numeric>

#include "reconfig/geometry/display_simplification.h"
#include "reconfig/view/box_view_camera.h"
#include "reconfig/view/scene_bounds.h"
#include "reconfig/view/view_candidates.h"

namespace reconfig::render {
namespace {

// Cameras counted in the first round, the highest coverage first: after each round the rest
// may be ruled out. Each round after counts twice as many (up to a batch of the counter), so
// that when none can be ruled out the rounds are few.
constexpr std::size_t kFirstRound = 64;

struct MostVisible {
  int index = 0;    // of the camera
  int counted = 0;  // cameras counted with their occluders
};

// The camera that sees the most visible pixels of `box` (the first of equals).
// A camera sees no more of the box than the box covers in its image (both counted in its
// tile of the atlas, so the same pixels exactly), so the cameras are
// counted in the order of their coverage (the first of equals first), and counting stops when
// the next one could neither see more than the best so far nor tie it with a lower index: the
// answer is the one counting every camera would give.
MostVisible most_visible(OcclusionCounter& counter, const Eigen::AlignedBox3d& box,
                         const std::vector<view::Camera>& cameras) {
  const std::vector<long> coverage = counter.coverage(box, cameras);
  std::vector<int> order(cameras.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return coverage[a] > coverage[b]; });
  int best = 0;
  long best_visible = -1;
  std::size_t counted = 0;
  const auto batch = static_cast<std::size_t>(counter.batch_size());
  for (std::size_t first = 0, size = kFirstRound; first < order.size(); first += size, size = std::min(2 * size, batch)) {
    const int next = order[first];
    if (coverage[next] < best_visible || (coverage[next] == best_visible && next > best)) break;
    const std::size_t last = std::min(order.size(), first + size);
    const std::vector<int> round(order.begin() + static_cast<long>(first), order.begin() + static_cast<long>(last));
    const std::vector<OcclusionCount> counts = counter.count_selected(box, cameras, round, false);
    counted = last;
    for (std::size_t k = first; k < last; ++k) {
      const int i = order[k];
      const long visible = counts[k - first].visible;
      if (visible > best_visible || (visible == best_visible && i < best)) {
        best = i;
        best_visible = visible;
      }
    }
  }
  return {best, static_cast<int>(counted)};
}

// The rows of F whose triangle's bounding box comes within `radius` of `center`.
Eigen::MatrixX3i triangles_within(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const Eigen::Vector3d& center,
                                  double radius) {
  std::vector<int> rows;
  for (int f = 0; f < F.rows(); ++f) {
    Eigen::AlignedBox3d box;
    for (int k = 0; k < 3; ++k) box.extend(Eigen::Vector3d(V.row(F(f, k))));
    if (box.squaredExteriorDistance(center) <= radius * radius) rows.push_back(f);
  }
  return F(rows, Eigen::all);
}

// A square on the plane z = height under `center`, big enough to cover the ball of `reach`
// around it: the ground, which hides what stands on it from below.
void add_floor(double height, const Eigen::Vector3d& center, double reach, Eigen::MatrixX3d& V, Eigen::MatrixX3i& F) {
  const long v = V.rows(), f = F.rows();
  V.conservativeResize(v + 4, 3);
  F.conservativeResize(f + 2, 3);
  const double r = 2 * reach;
  V.row(v) << center.x() - r, center.y() - r, height;
  V.row(v + 1) << center.x() + r, center.y() - r, height;
  V.row(v + 2) << center.x() + r, center.y() + r, height;
  V.row(v + 3) << center.x() - r, center.y() + r, height;
  F.row(f) << v, v + 1, v + 2;
  F.row(f + 1) << v, v + 2, v + 3;
}

}  // namespace

void posed_occluders(const scene::Reconfigurable& scene, int transition, double t, const std::vector<int>& excluded,
                     int max_triangles, Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, const Eigen::Vector3d& center,
                     double reach) {
  std::vector<bool> occludes(scene.parts.size(), true);
  for (int p : excluded) occludes[p] = false;
  std::vector<geometry::Mesh> kept;
  long triangles = 0;
  for (std::size_t p = 0; p < scene.parts.size(); ++p) {
    if (!occludes[p]) continue;
    const scene::Part& part = scene.parts[p];
    const Eigen::Isometry3d M = scene.pose_at(transition, static_cast<int>(p), t).to_isometry(part.center);
    geometry::Mesh posed;
    posed.V = (part.mesh.V * M.linear().transpose()).rowwise() + M.translation().transpose();
    posed.F = triangles_within(posed.V, part.mesh.F, center, reach);
    triangles += posed.F.rows();
    if (posed.F.rows() > 0) kept.push_back(std::move(posed));
  }
  if (triangles > max_triangles)
    for (geometry::Mesh& mesh : kept) {
      const double share = static_cast<double>(mesh.F.rows()) / static_cast<double>(triangles);
      mesh = geometry::simplify_for_display(mesh, std::max(4, static_cast<int>(share * max_triangles)));
    }
  long vertices = 0;
  triangles = 0;
  for (const geometry::Mesh& mesh : kept) {
    vertices += mesh.V.rows();
    triangles += mesh.F.rows();
  }
  V.resize(vertices, 3);
  F.resize(triangles, 3);
  long v = 0, f = 0;
  for (const geometry::Mesh& mesh : kept) {
    V.middleRows(v, mesh.V.rows()) = mesh.V;
    F.middleRows(f, mesh.F.rows()) = mesh.F.array() + static_cast<int>(v);
    v += mesh.V.rows();
    f += mesh.F.rows();
  }
}

BestViewRequest interval_view_request(const scene::Reconfigurable& scene, int transition,
                                      const collision::CollisionInterval& interval, double time) {
  BestViewRequest request;
  request.transition = transition;
  request.time = time;
  request.t0 = interval.t0;
  request.t1 = interval.t1;
  request.parts = interval.parts;
  request.box = interval.box;
  request.ground = scene.ground;
  return request;
}

BestView best_view(OcclusionCounter& counter, const scene::Reconfigurable& scene, const BestViewRequest& request) {
  // A box that is a point or a sliver still gets a view of some of its surroundings.
  const Eigen::AlignedBox3d bounds = view::scene_bounds_at(scene, request.transition, request.time);
  const double min_radius = 0.02 * (bounds.isEmpty() ? 1.0 : bounds.diagonal().norm());
  // Every eye lies on the sphere of this radius around X's center, so whatever can hide X lies
  // inside that ball (it holds X and the eye, hence the segments between them).
  const double reach = view::box_view_distance(request.box, request.fov_y, min_radius);
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  posed_occluders(scene, request.transition, request.time, request.parts, request.max_triangles, V, F,
                  request.box.center(), reach);
  if (request.ground) add_floor(bounds.min().z() - 1e-3 * bounds.diagonal().norm(), request.box.center(), reach, V, F);
  counter.set_occluders(V, F);

  const auto result = [&](const std::vector<Eigen::Vector3d>& directions, bool from_motion) {
    std::vector<view::Camera> cameras;
    cameras.reserve(directions.size());
    for (const Eigen::Vector3d& d : directions)
      cameras.push_back(view::box_view_camera(request.box, d, 1.0, request.fov_y, min_radius));
    const auto [best, counted] = most_visible(counter, request.box, cameras);
    const OcclusionCount pixels = counter.count_selected(request.box, cameras, {best}).front();  // with its total
    return BestView{cameras[best], directions[best], pixels, from_motion, static_cast<int>(directions.size()),
                    counted};
  };

  if (request.parts.size() == 2 && !request.always_sample) {
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
