// Resolution of collisions (the resolve module): energy and gradient of one collision interval,
// one hint, automatic resolution. Targets: energy + gradient of a bunny × armadillo interval
// ≤ 50 ms, one hint on the kitchen ≤ 20 ms, --auto on bench-table `unfold` ≤ 1 s and on the
// kitchen's `open_hasty` ≤ 10 s (with key times free to move: its pull-outs must wait).
//
//   build/bin/bench_resolve [--benchmark_filter=...]

#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <mutex>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/resolve/auto_resolve.h"
#include "reconfig/resolve/hints.h"
#include "reconfig/resolve/interval_energy.h"
#include "reconfig/scene/scene_file.h"
#include "scenes.h"

namespace {

using namespace reconfig;
namespace fs = std::filesystem;

enum SceneId : int { kBunnyArmadillo, kKitchenHasty, kBenchTable };

struct Fixture {
  std::string label;
  scene::Reconfigurable scene;
  int transition = 0;
  std::vector<collision::CollisionInterval> intervals;
  int part = 0;  ///< the part whose hint / gradient is asked for
};

const Fixture& fixture(int which) {
  static std::map<int, Fixture> cache;
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  if (auto it = cache.find(which); it != cache.end()) return it->second;
  Fixture f;
  const fs::path examples = fs::path(RECONFIG_SOURCE_DIR) / "examples";
  switch (which) {
    case kBunnyArmadillo:
      f.label = "bunny through armadillo";
      f.scene = bench::sweep_scene("armadillo.off", "bunny00.off");
      break;
    case kKitchenHasty:
      f.label = "kitchen, open_hasty";
      f.scene = scene::load_scene(examples / "kitchen" / "scene.json");
      f.transition = f.scene.find_transition("open_hasty");
      break;
    default:
      f.label = "bench-table, unfold";
      f.scene = scene::load_scene(examples / "bench-table" / "scene.json");
      f.transition = f.scene.find_transition("unfold");
      break;
  }
  collision::CollisionRequest request;
  request.transitions = {f.transition};
  f.intervals = collision::detect_collisions(f.scene, request).transitions.at(0).intervals;
  if (f.intervals.empty()) throw std::runtime_error(f.label + ": no collision to resolve");
  // The longest interval, and its part that moves (the hint's subject).
  const auto longest = std::max_element(f.intervals.begin(), f.intervals.end(),
                                        [](const auto& a, const auto& b) { return a.duration() < b.duration(); });
  f.intervals = {*longest};
  for (int p : longest->parts)
    if (!resolve::key_dofs(f.scene, f.transition, p).empty()) f.part = p;
  return cache.emplace(which, std::move(f)).first->second;
}

void BM_EnergyAndGradient(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  resolve::ShapeCache shapes;
  shapes.shape(f.scene, f.intervals[0].parts[0]);  // built once per geometry, as in the studio
  shapes.shape(f.scene, f.intervals[0].parts[1]);
  const std::vector<resolve::KeyDof> dofs = resolve::key_dofs(f.scene, f.transition, f.part);
  std::size_t samples = 0;
  for (auto _ : state) {
    const resolve::IntervalEnergy energy = resolve::interval_energy(f.scene, shapes, f.transition, f.intervals[0]);
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(resolve::dof_coordinates(dofs));
    samples = 0;
    for (const auto& [pair, pair_energy] : energy.pairs) {
      gradient += resolve::energy_gradient(f.scene, f.transition, f.part, dofs, pair_energy, pair[0] == f.part);
      samples += pair_energy.samples.size();
    }
    benchmark::DoNotOptimize(gradient.data());
  }
  state.SetLabel(f.label);
  state.counters["time_samples"] = static_cast<double>(samples);
  state.counters["triangles"] = f.scene.parts[f.intervals[0].parts[0]].mesh.face_count() +
                                f.scene.parts[f.intervals[0].parts[1]].mesh.face_count();
}
BENCHMARK(BM_EnergyAndGradient)->Arg(kBunnyArmadillo)->ArgName("scene")->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Hint(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  resolve::ShapeCache shapes;
  for (int p : f.intervals[0].parts) shapes.shape(f.scene, p);
  for (auto _ : state) {
    const resolve::HintResult hint =
        resolve::compute_hints(f.scene, shapes, {.transition = f.transition, .part = f.part, .intervals = f.intervals});
    benchmark::DoNotOptimize(hint.energy);
  }
  state.SetLabel(f.label + ": " + f.scene.parts[f.part].name);
}
BENCHMARK(BM_Hint)->Arg(kKitchenHasty)->ArgName("scene")->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_AutoResolve(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  bool free = false;
  std::size_t rounds = 0;
  for (auto _ : state) {
    // Key times may move: the kitchen's pull-outs must wait for its doors.
    const resolve::AutoResolveResult result =
        resolve::auto_resolve(f.scene, {.transition = f.transition, .move_times = true});
    free = result.collision_free;
    rounds = result.rounds.size();
  }
  state.SetLabel(f.label + (free ? ": collision-free" : ": collisions remain"));
  state.counters["rounds"] = static_cast<double>(rounds);
}
BENCHMARK(BM_AutoResolve)->Arg(kBenchTable)->ArgName("scene")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AutoResolve)->Arg(kKitchenHasty)->ArgName("scene")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
