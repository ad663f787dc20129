// Sculpting with sweepers (the sculpt module). Targets: one sub-step of a sphere tool on a
// 100 K-vertex mesh, the tool reaching 10 % of it, normals included: ≤ 5 ms; a whole drag frame
// with remeshing: ≤ 16 ms. The mesh is an icosphere with 163,842 vertices (more than the target's
// 100 K); the tool (radius 0.4, coating 0.232 on the unit sphere) reaches 10 % of the vertices.
//
//   build/bin/bench_sculpt [--benchmark_filter=...]

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "reconfig/geometry/primitives.h"
#include "reconfig/sculpt/sculpt_stroke.h"
#include "reconfig/sculpt/vertex_normals.h"

namespace {

using namespace reconfig;

struct Fixture {
  geometry::Mesh mesh = geometry::make_sphere(1.0, 7);
  Eigen::MatrixX3d normals = sculpt::vertex_normals(mesh);
  sculpt::SculptMesh sculpted{mesh, normals};  ///< with its index and room to grow, as a drag keeps it
  sculpt::Tool tool = sculpt::Tool::sphere(0.4, {1, 0, 0}, 0.232);
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

/// A stroke of one sub-step (|d| below the bound's λ/1.875), back and forth on a copy of the
/// mesh (the shared one stays put whatever the number of iterations).
void run_strokes(benchmark::State& state, const sculpt::StrokeOptions& options) {
  const Fixture& f = fixture();
  geometry::Mesh mesh = f.mesh;
  Eigen::MatrixX3d normals = f.normals;
  sculpt::Tool tool = f.tool;
  sculpt::ToolMotion motion = sculpt::ToolMotion::translation({0.1, 0.02, 0});
  int substeps = 0, moved = 0;
  for (auto _ : state) {
    const sculpt::StrokeResult result = sculpt::deform_points({{tool, motion}}, options, mesh.V, normals);
    if (!result.applied) state.SkipWithError(result.refusal.c_str());
    substeps = result.substeps;
    moved = result.vertices_moved;
    tool = result.tools.front();
    motion = motion.inverse();
  }
  state.counters["substeps"] = substeps;
  state.counters["vertices"] = mesh.vertex_count();
  state.counters["moved"] = moved;
}

/// Arguments: the det J grid (8³ or none), the threads (1: its CPU time is the whole work).
void BM_SubstepSphereTool(benchmark::State& state) {
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(1));
  sculpt::StrokeOptions options;
  options.grid = static_cast<int>(state.range(0));
  run_strokes(state, options);
}
BENCHMARK(BM_SubstepSphereTool)->Args({8, 2})->Args({0, 2})->Args({8, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SubstepSphereToolBlended(benchmark::State& state) {
  sculpt::StrokeOptions options;
  options.blended = true;
  run_strokes(state, options);
}
BENCHMARK(BM_SubstepSphereToolBlended)->Unit(benchmark::kMillisecond)->UseRealTime();

/// One stroke of one sub-step on a fresh copy of the sculpting mesh (its storage, with the room
/// it keeps to grow, and its index), through `sculpt_mesh` with the given options. The copies
/// are assigned while the timer is paused, so neither they nor freeing the last frame's mesh is
/// timed: a drag keeps the mesh from frame to frame.
void run_mesh_stroke(benchmark::State& state, const sculpt::StrokeOptions& options) {
  const Fixture& f = fixture();
  const sculpt::ToolMotion motion = sculpt::ToolMotion::translation({0.1, 0.02, 0});
  sculpt::StrokeResult result;
  sculpt::SculptMesh mesh;
  for (auto _ : state) {
    state.PauseTiming();
    mesh = f.sculpted;
    state.ResumeTiming();
    result = sculpt::sculpt_mesh({{f.tool, motion}}, options, mesh);
    if (!result.applied) state.SkipWithError(result.refusal.c_str());
  }
  state.counters["moved"] = result.vertices_moved;
  state.counters["splits"] = result.splits;
  state.counters["collapses"] = result.collapses;
}

/// A drag frame: the one-sub-step stroke remeshed in its reach (edges kept between 0.004 and
/// 0.016, around the icosphere's 0.0077), no self-intersection check. Argument: the threads.
void BM_DragFrameWithRemeshing(benchmark::State& state) {
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(0));
  sculpt::StrokeOptions options;
  options.remesh = {0.016, 0.004};
  options.check_self_intersections = false;
  run_mesh_stroke(state, options);
}
BENCHMARK(BM_DragFrameWithRemeshing)->Arg(2)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The same stroke without remeshing but with the exact self-intersection test of the whole mesh.
void BM_StrokeWithSelfIntersectionCheck(benchmark::State& state) { run_mesh_stroke(state, {}); }
BENCHMARK(BM_StrokeWithSelfIntersectionCheck)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
