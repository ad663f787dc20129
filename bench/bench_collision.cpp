// Spacetime collision engine vs the reference check, on real meshes (CGAL demo data).
//
//   build/bin/bench_collision [--benchmark_filter=...]
//
// Scenes: a CGAL mesh held still and another one sweeping through it along a curved path while
// turning 90° (both scaled to about 1 m), so they collide midway. Measured: full detection at
// 1 mm tolerance (28-DOP, and 8/80-DOP for comparison), the update after moving one keyframe,
// and the reference check at the same time resolution as the engine's proxies.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "reconfig/collision/reference_check.h"
#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/geometry/load_mesh.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/history.h"
#include "reconfig/scene/part.h"

namespace {

using namespace reconfig;
namespace fs = std::filesystem;

/// `data/meshes/<name>` of the CGAL demo data, extracted once next to the binary.
geometry::Mesh cgal_mesh(const std::string& name) {
  const fs::path root = fs::temp_directory_path() / "reconfig-bench-data";
  const fs::path file = root / "data" / "meshes" / name;
  if (!fs::exists(file)) {
    fs::create_directories(root);
    const std::string command = "tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C " + root.string() + " data/meshes/" + name;
    if (std::system(command.c_str()) != 0) throw std::runtime_error("cannot extract " + name + " (libcgal-demo)");
  }
  geometry::Mesh mesh = geometry::load_mesh(file);
  // Scale to a 1 m bounding box centered at the origin.
  const Eigen::RowVector3d lo = mesh.V.colwise().minCoeff(), hi = mesh.V.colwise().maxCoeff();
  mesh.V = ((mesh.V.rowwise() - (lo + hi) / 2) / (hi - lo).maxCoeff()).eval();
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

/// `still` rests at the origin; `moving` sweeps from x = −1.3 to x = 1.3 over a hump, turning 90°.
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
  scene.transitions = {{"sweep", "start", "end", true, {{"moving", track}}}};
  return scene;
}

struct Fixture {
  scene::Reconfigurable scene;
  collision::BodyTrees trees;
  int triangles = 0;
};

const Fixture& fixture(int which) {
  static std::map<int, Fixture> cache;
  auto it = cache.find(which);
  if (it != cache.end()) return it->second;
  Fixture f;
  f.scene = which == 0 ? sweep_scene("elephant.off", "elephant.off") : sweep_scene("armadillo.off", "bunny00.off");
  f.trees = collision::build_body_trees(f.scene);
  for (const auto& part : f.scene.parts) f.triangles += part.mesh.face_count();
  return cache.emplace(which, std::move(f)).first->second;
}

collision::DopFamily family(int dop) {
  return dop == 8 ? collision::DopFamily::k8 : dop == 80 ? collision::DopFamily::k80 : collision::DopFamily::k28;
}

void BM_FullDetection(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  collision::DetectorOptions options;
  options.tolerance = 1e-3;
  options.dop = family(static_cast<int>(state.range(1)));
  long contacts = 0, samples = 0;
  for (auto _ : state) {
    collision::SpacetimeDetector detector(0, options);
    detector.detect(f.scene, f.trees);
    contacts = static_cast<long>(detector.contacts().size());
    samples = detector.last_stats().proxy_samples;
  }
  state.counters["triangles"] = f.triangles;
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["proxy_samples"] = static_cast<double>(samples);
}
BENCHMARK(BM_FullDetection)->ArgsProduct({{0, 1}, {28}})->ArgNames({"scene", "dop"})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullDetection)->ArgsProduct({{0}, {8, 80}})->ArgNames({"scene", "dop"})->Unit(benchmark::kMillisecond);

void BM_UpdateAfterKeyEdit(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  scene::Reconfigurable scene = f.scene;
  collision::SpacetimeDetector detector(0, {});
  detector.detect(scene, f.trees);
  scene::History history;
  detector.update(scene, f.trees, history.execute(scene, scene::insert_key("sweep", "moving", scene::KeyKind::kTranslation, 0.8)));
  motion::TranslationKey key = std::get<scene::KeyframedTrack>(scene.transitions[0].tracks.at("moving")).translation[1];
  double shift = 0.002;
  for (auto _ : state) {
    key.point.z() += shift;
    key.in.z() += shift;
    key.out.z() += shift;
    shift = -shift;
    const scene::DirtySet dirty = history.execute(scene, scene::set_translation_key("sweep", "moving", 1, key));
    detector.update(scene, f.trees, dirty);
  }
  state.counters["triangles"] = f.triangles;
}
BENCHMARK(BM_UpdateAfterKeyEdit)->Arg(0)->Arg(1)->ArgName("scene")->Unit(benchmark::kMillisecond);

void BM_ReferenceCheck(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  collision::SpacetimeDetector detector(0, {});
  detector.detect(f.scene, f.trees);
  collision::ReferenceCheckRequest request;
  request.samples = static_cast<int>(detector.last_stats().proxy_samples);  // same time resolution
  for (auto _ : state) benchmark::DoNotOptimize(collision::reference_check(f.scene, request));
  state.counters["samples"] = request.samples;
  state.counters["triangles"] = f.triangles;
}
BENCHMARK(BM_ReferenceCheck)->Arg(0)->Arg(1)->ArgName("scene")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
