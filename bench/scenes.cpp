#include "scenes.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/part.h"

namespace reconfig::bench {

namespace fs = std::filesystem;

geometry::Mesh cgal_mesh(const std::string& name, double size) {
  const fs::path root = fs::temp_directory_path() / "reconfig-bench-data";
  const fs::path file = root / "data" / "meshes" / name;
  if (!fs::exists(file)) {
    fs::create_directories(root);
    const std::string command = "tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C " + root.string() + " data/meshes/" + name;
    if (std::system(command.c_str()) != 0) throw std::runtime_error("cannot extract " + name + " (libcgal-demo)");
  }
  geometry::Mesh mesh = geometry::load_mesh(file);
  const Eigen::RowVector3d lo = mesh.V.colwise().minCoeff(), hi = mesh.V.colwise().maxCoeff();
  mesh.V = ((mesh.V.rowwise() - (lo + hi) / 2) * (size / (hi - lo).maxCoeff())).eval();
  return mesh;
}

scene::Part make_part(const std::string& name, geometry::Mesh mesh) {
  scene::Part part;
  part.name = name;
  part.source = scene::EditedMesh{};
  part.mesh = std::move(mesh);
  part.center = scene::part_center(part.mesh);
  return part;
}

std::vector<motion::TranslationKey> polyline_keys(const std::vector<std::pair<double, Eigen::Vector3d>>& points) {
  std::vector<motion::TranslationKey> keys;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d p = points[k].second;
    const Eigen::Vector3d prev = k > 0 ? points[k - 1].second : p, next = k + 1 < points.size() ? points[k + 1].second : p;
    keys.push_back({points[k].first, p, p + (prev - p) / 3, p + (next - p) / 3});
  }
  return keys;
}

scene::Transition one_track_transition(const std::string& name, const std::string& part, scene::KeyframedTrack track) {
  scene::Transition transition;
  transition.name = name;
  transition.from = "start";
  transition.to = "end";
  transition.tracks.emplace(part, std::move(track));
  return transition;
}

scene::Reconfigurable sweep_scene(const std::string& still, const std::string& moving) {
  scene::Reconfigurable scene;
  scene.parts = {make_part("still", cgal_mesh(still)), make_part("moving", cgal_mesh(moving))};
  const Eigen::Vector3d a(-1.3, 0.1, 0), b(1.3, -0.1, 0.05);
  const Eigen::Quaterniond qa = Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond qb(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  scene.states = {{"start", {{"moving", {qa, a}}}}, {"end", {{"moving", {qb, b}}}}};
  scene::KeyframedTrack track;
  track.translation = {{0.0, a, a, a + Eigen::Vector3d(0.6, 0, 0.3)}, {1.0, b, b + Eigen::Vector3d(-0.6, 0, 0.3), b}};
  track.rotation = {{0.0, qa}, {1.0, qb}};
  scene.transitions = {one_track_transition("sweep", "moving", track)};
  return scene;
}

scene::Reconfigurable gallery_scene() {
  scene::Reconfigurable scene;
  const geometry::Mesh bunny = cgal_mesh("bunny00.off"), armadillo = cgal_mesh("armadillo.off");
  for (int k = 0; k < 16; ++k) {
    geometry::Mesh mesh = k % 2 == 0 ? bunny : armadillo;
    const int row = k / 8, column = k % 8;
    mesh.V.rowwise() += Eigen::RowVector3d(1.2 * column, row == 0 ? -0.8 : 0.8, 0);
    scene.parts.push_back(make_part("statue_" + std::to_string(k), std::move(mesh)));
  }
  scene.parts.push_back(make_part("walker", cgal_mesh("armadillo.off", 0.45)));
  const Eigen::Vector3d a(-1.0, 0, -0.2), m(3.6, 0.2, -0.2), b(9.4, 0, -0.2);
  const Eigen::Quaterniond qa = Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond qb(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  scene.states = {{"start", {{"walker", {qa, a}}}}, {"end", {{"walker", {qb, b}}}}};
  scene::KeyframedTrack track;
  track.translation = polyline_keys({{0.0, a}, {0.5, m}, {1.0, b}});
  track.translation[1].in = m - Eigen::Vector3d(1.5, 0, 0);  // a smooth swerve through the middle key
  track.translation[1].out = m + Eigen::Vector3d(1.5, 0, 0);
  track.rotation = {{0.0, qa}, {1.0, qb}};
  scene.transitions = {one_track_transition("walk", "walker", track)};
  return scene;
}

scene::Reconfigurable crowd_scene(int parts, int moving) {
  scene::Reconfigurable scene;
  const int side = static_cast<int>(std::ceil(std::sqrt(parts)));
  scene::State start{"start", {}}, end{"end", {}};
  scene::Transition rise;
  rise.name = "rise";
  rise.from = "start";
  rise.to = "end";
  for (int k = 0; k < parts; ++k) {
    const std::string name = "box_" + std::to_string(k);
    scene.parts.push_back(make_part(name, geometry::make_box({1, 1, 1})));
    const Eigen::Vector3d a(3.0 * (k % side), 3.0 * (k / side), 0), b = a + Eigen::Vector3d(0, 0, k < moving ? 1 : 0);
    start.poses[name] = {Eigen::Quaterniond::Identity(), a};
    end.poses[name] = {Eigen::Quaterniond::Identity(), b};
    scene::KeyframedTrack track;
    track.translation = polyline_keys({{0.0, a}, {1.0, b}});
    if (k < moving) rise.tracks.emplace(name, track);
  }
  scene.states = {start, end};
  scene.transitions = {rise};
  return scene;
}

}  // namespace reconfig::bench
