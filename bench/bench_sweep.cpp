// Swept volumes and carving (the sweep module). Targets: the swept volume of the CGAL bunny
// translated by its size while turning 90°, 128 cells along the longest side, ≤ 1 s; the whole
// carve of bench-table's backrest by the armrests ≤ 2 s.
//
//   build/bin/bench_sweep [--benchmark_filter=...]

#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <numbers>

#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/save_mesh.h"
#include "reconfig/scene/scene_file.h"
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
  if (getenv("SWEEP_TRACE")) {
    auto start = std::chrono::steady_clock::now();
    double last = -1;
    request.progress = [&](double f) { if (f - last > 0.099 || f == 1.0) { last = f; fprintf(stderr, "%.2f at %.3f\n", f, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()); } return true; };
    sweep::swept_volume(bunny, motion, request);
    fprintf(stderr, "done at %.3f\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    request.progress = {};
    geometry::save_obj("/tmp/bunny_sweep.obj", sweep::swept_volume(bunny, motion, request).mesh);
  }
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

}  // namespace

BENCHMARK_MAIN();
