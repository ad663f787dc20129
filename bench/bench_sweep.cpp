// Swept volumes and carving (the sweep module). Targets: the swept volume of the CGAL bunny
// translated by its size while turning 90°, 128 cells along the longest side, ≤ 1 s; the whole
// carve of bench-table's backrest by the armrests ≤ 2 s; the screw envelope of a ~100K-triangle part
// ≤ 50 ms (the studio redraws it while keys are dragged).
//
//   build/bin/bench_sweep [--benchmark_filter=...]

#include <benchmark/benchmark.h>

#include <filesystem>
#include <numbers>

#include "reconfig/geometry/mesh_check.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/sweep/carve_part.h"
#include "reconfig/sweep/screw_envelope.h"
#include "reconfig/sweep/swept_volume.h"
#include "scenes.h"

namespace {

using namespace reconfig;
namespace fs = std::filesystem;

/// t ↦ turn by 90°·t about z through the origin, then slide by (1, 0, 0)·t.
sweep::RelativeMotion bunny_motion(double radius) {
  return sweep::RelativeMotion(
      [](double t) {
        Eigen::Isometry3d g = Eigen::Isometry3d::Identity();
        g.translate(Eigen::Vector3d(t, 0, 0)).rotate(Eigen::AngleAxisd(std::numbers::pi / 2 * t, Eigen::Vector3d::UnitZ()));
        return g;
      },
      [radius](double a, double b) { return (1.0 + radius * std::numbers::pi / 2) * (b - a); }, 0, 1);
}

void BM_SweptVolumeBunny(benchmark::State& state) {
  const geometry::Mesh bunny = bench::cgal_mesh("bunny00.off", 1.0);
  const double radius = bunny.V.rowwise().norm().maxCoeff();
  const sweep::RelativeMotion motion = bunny_motion(radius);
  sweep::SweptVolumeRequest request;
  request.offset = 0.01;
  sweep::SweptVolumeResult result;
  for (auto _ : state) result = sweep::swept_volume(bunny, motion, request);
  const geometry::MeshReport report = geometry::check_mesh(result.mesh);
  state.counters["part_triangles"] = bunny.face_count();
  state.counters["cells_longest"] = std::max({result.grid_size[0], result.grid_size[1], result.grid_size[2]});
  state.counters["time_samples"] = result.time_samples;
  state.counters["band_voxels"] = double(result.active_voxels);
  state.counters["triangles"] = result.mesh.face_count();
  state.counters["components"] = report.component_count;
  state.counters["valid_solid"] = report.is_valid_solid();
  state.SetLabel("bunny00, 1 m slide + 90° turn");
}
BENCHMARK(BM_SweptVolumeBunny)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

/// The whole carve of `reconfig carve examples/bench-table/scene.json --transition unfold --part
/// backrest --by armrest_left,armrest_right --offset 0.005` (both sweeps, the exact subtraction).
void BM_CarveBenchTable(benchmark::State& state) {
  const scene::Reconfigurable scene =
      scene::load_scene(fs::path(RECONFIG_SOURCE_DIR) / "examples" / "bench-table" / "scene.json");
  sweep::CarveRequest request;
  request.transition = scene.find_transition("unfold");
  request.part = scene.find_part("backrest");
  request.carvers = {scene.find_part("armrest_left"), scene.find_part("armrest_right")};
  request.sweep.offset = 0.005;
  sweep::CarveResult result;
  for (auto _ : state) result = sweep::carve_part(scene, request);
  if (!result.ok()) state.SkipWithError(result.problem.c_str());
  state.counters["triangles"] = result.mesh.face_count();
  state.counters["time_samples"] = result.sweeps.empty() ? 0 : result.sweeps[0].time_samples;
  state.counters["sweep_triangles"] = result.sweeps.empty() ? 0 : result.sweeps[0].mesh.face_count();
  state.SetLabel("bench-table backrest by both armrests");
}
BENCHMARK(BM_CarveBenchTable)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

/// The bunny's screw: turn 90° about z while sliding by its size along x (as above), 5° steps.
motion::ScrewMotion bunny_screw() {
  Eigen::Isometry3d end = Eigen::Isometry3d::Identity();
  end.translate(Eigen::Vector3d(1, 0, 0)).rotate(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
  return motion::ScrewMotion(Eigen::Isometry3d::Identity(), end);
}

/// Arg 0: the bunny (75 K triangles); 1: the bunny and the armadillo beside it as one part (127 K).
geometry::Mesh envelope_part(int which) {
  geometry::Mesh bunny = bench::cgal_mesh("bunny00.off", 1.0);
  if (which == 0) return bunny;
  const geometry::Mesh armadillo = bench::cgal_mesh("armadillo.off", 1.0);
  geometry::Mesh both;
  both.V.resize(bunny.vertex_count() + armadillo.vertex_count(), 3);
  both.V << bunny.V, (armadillo.V.rowwise() + Eigen::RowVector3d(0, 1.5, 0));
  both.F.resize(bunny.face_count() + armadillo.face_count(), 3);
  both.F << bunny.F, (armadillo.F.array() + bunny.vertex_count()).matrix();
  return both;
}

/// The redraw: silhouettes and quads from a part whose normals and edges are kept.
void BM_ScrewEnvelope(benchmark::State& state) {
  const sweep::EnvelopePart part(envelope_part(static_cast<int>(state.range(0))));
  const motion::ScrewMotion screw = bunny_screw();
  sweep::ScrewEnvelope envelope;
  for (auto _ : state) envelope = sweep::screw_envelope(part, std::span(&screw, 1));
  state.counters["part_triangles"] = part.mesh().face_count();
  state.counters["silhouette_segments"] = envelope.silhouette_segments;
  state.counters["steps"] = envelope.steps;
  state.counters["triangles"] = envelope.mesh.face_count();
  state.SetLabel(state.range(0) == 0 ? "bunny00, 1 m slide + 90° turn, one screw" : "bunny00 + armadillo, same screw");
}
BENCHMARK(BM_ScrewEnvelope)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

/// Once per mesh edit: the normals, the edges and their convexity.
void BM_ScrewEnvelopePart(benchmark::State& state) {
  const geometry::Mesh mesh = envelope_part(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(sweep::EnvelopePart(mesh).edges().size());
  state.counters["part_triangles"] = mesh.face_count();
  state.SetLabel(state.range(0) == 0 ? "bunny00 normals and edges" : "bunny00 + armadillo normals and edges");
}
BENCHMARK(BM_ScrewEnvelopePart)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
