// Spacetime collision engine vs the reference check and FCL 0.7, on real meshes (CGAL demo data)
// and on the many-part kitchen example, from 1 K to 1 M triangles.
//
//   build/bin/bench_collision [--benchmark_filter=...]
//   reconfig bench collision [--filter ...] [--json]     (the same, with a summary table)
//
// Scenes (the `scene:N` argument of every benchmark):
//   0  elephant through elephant        11 K triangles   CGAL mesh held still, another one
//   1  bunny through armadillo         127 K triangles   sweeping through it along a curved
//   2  eight through eight             1.3 K triangles   path while turning 90° (1 m boxes)
//   3  kitchen, transition open_hasty  1.2 K triangles, 22 parts (examples/kitchen; collides)
//   4  kitchen, transition open        1.2 K triangles, 22 parts (collision-free)
//   5  gallery                         1.07 M triangles: 16 still statues (8 bunnies, 8
//      armadillos) in two rows and a small armadillo walking down the corridor between them,
//      swerving into one statue midway. Slow (minutes); run it alone with
//      --benchmark_filter='scene:5'.
//   6  crowd                            120 K triangles: 10,000 unit cubes 3 m apart, 100 of
//      them rising 1 m: the broad phase (memory linear in parts and candidate pairs).
// Measured for each: full detection at 1 mm tolerance with the 28-, 8- and 80-DOP families,
// the update after moving one translation key, the reference check and FCL 0.7 (if found at
// configure time) at the same time resolution as the engine's proxies: the number of distinct
// sample times of all parts' proxies (28-DOP, 1 mm). FCL gets the engine's exact sample times,
// the reference check (evenly spaced samples only) the same number of them. FCL is asked twice:
// whether each pair of parts intersects (BM_FclPerStep), and for every intersecting triangle
// pair (BM_FclAllContactsPerStep, the engine's and the reference's output); neither gives any
// guarantee between the samples. The baselines that make the engine's promise (fcl_baselines.h):
// FCL discrete at the step where no vertex moves more than the tolerance between two samples
// (BM_FclGuaranteedStep, all:0 whether / all:1 every contact, with the samples it needed), and
// FCL's continuous collision per pair of parts over each proxy step (BM_FclContinuous: first
// contacts only, counted against the engine's intervals: what it misses).
// Every benchmark reports wall-clock time ("Time") and the whole process's CPU time over all its
// threads ("CPU"), which the virtual machine's steal time does not inflate.

#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>

#include "reconfig/collision/reference_check.h"
#include "reconfig/collision/spacetime_detector.h"
#include "reconfig/collision/spacetime_proxy.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/history.h"
#include "reconfig/scene/scene_file.h"
#include "scenes.h"

#ifdef RECONFIG_HAVE_FCL
#include "fcl_baselines.h"
#include "guaranteed_steps.h"
#endif

namespace {

using namespace reconfig;
using namespace reconfig::bench;
namespace fs = std::filesystem;

enum SceneId : int { kElephant, kBunnyArmadillo, kEight, kKitchenHasty, kKitchen, kGallery, kCrowd };

struct Fixture {
  std::string label;
  scene::Reconfigurable scene;
  collision::BodyTrees trees;
  int transition = 0;
  /// The update benchmark moves translation key `edit_key` of `edit_part` up and down by 2 mm
  /// (after inserting a key at t = 0.8 if `insert_edit_key`).
  std::string edit_part;
  int edit_key = 1;
  bool insert_edit_key = false;
  int triangles = 0;
  /// Distinct sample times of every part's proxy (1 mm): the engine's time resolution.
  std::vector<double> sample_times;
};

const Fixture& fixture(int which) {
  static std::map<int, Fixture> cache;
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  auto it = cache.find(which);
  if (it != cache.end()) return it->second;
  Fixture f;
  const fs::path kitchen = fs::path(RECONFIG_SOURCE_DIR) / "examples" / "kitchen" / "scene.json";
  switch (which) {
    case kElephant:
      f.label = "elephant through elephant";
      f.scene = sweep_scene("elephant.off", "elephant.off");
      break;
    case kBunnyArmadillo:
      f.label = "bunny through armadillo";
      f.scene = sweep_scene("armadillo.off", "bunny00.off");
      break;
    case kEight:
      f.label = "eight through eight";
      f.scene = sweep_scene("eight.off", "eight.off");
      break;
    case kKitchenHasty:
    case kKitchen:
      f.scene = scene::load_scene(kitchen);
      f.transition = f.scene.find_transition(which == kKitchen ? "open" : "open_hasty");
      f.label = which == kKitchen ? "kitchen, open (collision-free)" : "kitchen, open_hasty (collides)";
      f.edit_part = "pullout_shelf";  // key 1: where the shelf starts to slide out
      break;
    case kGallery:
      f.label = "gallery: walker between 16 statues";
      f.scene = gallery_scene();
      f.edit_part = "walker";
      break;
    case kCrowd:
      f.label = "crowd: 10,000 boxes, 100 rising";
      f.scene = crowd_scene();
      f.edit_part = "box_0";
      break;
    default:
      throw std::runtime_error("no such scene");
  }
  if (f.edit_part.empty()) {
    f.edit_part = "moving";
    f.insert_edit_key = true;
  }
  f.trees = collision::build_body_trees(f.scene);
  std::set<double> times;
  for (int p = 0; p < static_cast<int>(f.scene.parts.size()); ++p) {
    f.triangles += f.scene.parts[p].mesh.face_count();
    for (double t : collision::build_part_proxy(f.scene, f.transition, p, 1e-3).times) times.insert(t);
  }
  f.sample_times.assign(times.begin(), times.end());
  return cache.emplace(which, std::move(f)).first->second;
}

void describe(benchmark::State& state, const Fixture& f) {
  state.SetLabel(f.label);
  state.counters["triangles"] = f.triangles;
  state.counters["parts"] = static_cast<double>(f.scene.parts.size());
  state.counters["samples"] = static_cast<double>(f.sample_times.size());
}

void BM_FullDetection(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  collision::DetectorOptions options;
  options.tolerance = 1e-3;
  options.dop = *collision::dop_family(static_cast<int>(state.range(1)));  // the benchmarks' dop: 8, 28 or 80
  options.all_contacts = state.range(2) != 0;
  long contacts = 0, groups = 0, samples = 0, bound_tests = 0, narrow = 0;
  for (auto _ : state) {
    collision::SpacetimeDetector detector(f.transition, options);
    detector.detect(f.scene, f.trees);
    contacts = static_cast<long>(detector.contacts().size());
    groups = static_cast<long>(detector.groups().size());
    samples = detector.last_stats().proxy_samples;
    bound_tests = detector.last_stats().bound_tests;
    narrow = detector.last_stats().narrow_phase;
  }
  describe(state, f);
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["groups"] = static_cast<double>(groups);
  state.counters["proxy_samples"] = static_cast<double>(samples);  // summed over the parts
  state.counters["bound_tests"] = static_cast<double>(bound_tests);
  state.counters["narrow_phase"] = static_cast<double>(narrow);
}
// Scenes 0–4 with every DOP family, stopping early (all:0) or finding every contact (all:1,
// 28-DOP); the 1 M-triangle gallery with 28 only.
BENCHMARK(BM_FullDetection)
    ->ArgsProduct({{kElephant, kBunnyArmadillo, kEight, kKitchenHasty, kKitchen}, {28, 8, 80}, {0}})
    ->ArgNames({"scene", "dop", "all"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FullDetection)
    ->ArgsProduct({{kElephant, kBunnyArmadillo, kEight, kKitchenHasty, kKitchen}, {28}, {1}})
    ->ArgNames({"scene", "dop", "all"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FullDetection)
    ->Args({kCrowd, 28, 0})
    ->ArgNames({"scene", "dop", "all"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FullDetection)
    ->Args({kGallery, 28, 0})
    ->ArgNames({"scene", "dop", "all"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime()
    ->Iterations(1);

void BM_UpdateAfterKeyEdit(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  scene::Reconfigurable scene = f.scene;
  const std::string transition = scene.transitions[f.transition].name;
  collision::SpacetimeDetector detector(f.transition, {});
  detector.detect(scene, f.trees);
  scene::History history;
  if (f.insert_edit_key)
    detector.update(scene, f.trees,
                    history.execute(scene, scene::insert_key(transition, f.edit_part, scene::KeyKind::kTranslation, 0.8)));
  motion::TranslationKey key =
      std::get<scene::KeyframedTrack>(scene.transitions[f.transition].tracks.at(f.edit_part)).translation[f.edit_key];
  double shift = 0.002;
  for (auto _ : state) {
    key.point.z() += shift;
    key.in.z() += shift;
    key.out.z() += shift;
    shift = -shift;
    const scene::DirtySet dirty = history.execute(scene, scene::set_translation_key(transition, f.edit_part, f.edit_key, key));
    detector.update(scene, f.trees, dirty);
  }
  describe(state, f);
  state.counters["contacts"] = static_cast<double>(detector.contacts().size());
  state.counters["bound_tests"] = static_cast<double>(detector.last_stats().bound_tests);  // of the last update
  state.counters["narrow_phase"] = static_cast<double>(detector.last_stats().narrow_phase);
}
BENCHMARK(BM_UpdateAfterKeyEdit)
    ->ArgsProduct({{kElephant, kBunnyArmadillo, kEight, kKitchenHasty, kKitchen}})
    ->ArgName("scene")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_UpdateAfterKeyEdit)->Arg(kGallery)->ArgName("scene")->Unit(benchmark::kMillisecond)->UseRealTime()
    ->MeasureProcessCPUTime()->Iterations(2);

void BM_ReferenceCheck(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  collision::ReferenceCheckRequest request;
  request.samples = static_cast<int>(f.sample_times.size());  // same time resolution
  request.transitions = {f.transition};
  long colliding = 0;
  for (auto _ : state) {
    const collision::ReferenceCheckResult result = collision::reference_check(f.scene, request);
    std::set<int> samples;
    for (const auto& contact : result.contacts.front()) samples.insert(contact.sample);
    colliding = static_cast<long>(samples.size());
  }
  describe(state, f);
  state.counters["colliding_samples"] = static_cast<double>(colliding);
}
BENCHMARK(BM_ReferenceCheck)
    ->ArgsProduct({{kElephant, kBunnyArmadillo, kEight, kKitchenHasty, kKitchen}})
    ->ArgName("scene")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_ReferenceCheck)->Arg(kGallery)->ArgName("scene")->Unit(benchmark::kMillisecond)->UseRealTime()
    ->MeasureProcessCPUTime()->Iterations(1);

#ifdef RECONFIG_HAVE_FCL
/// FCL 0.7's own BVHs (built once per part, not timed), the engine's result (28-DOP, 1 mm: for
/// the comparisons) and the samples that make the engine's promise, per scene.
struct FclFixture {
  FclParts parts;
  std::vector<collision::CollisionInterval> engine_groups;
  GuaranteedSamples guaranteed;  ///< no vertex moves more than 1 mm between two samples
  /// The time the fastest vertex takes to move by the tolerance: how far apart in time two
  /// answers may be and still agree.
  double time_tolerance = 0;
};

const FclFixture& fcl_fixture(int which) {
  static std::map<int, FclFixture> cache;
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  auto it = cache.find(which);
  if (it != cache.end()) return it->second;
  const Fixture& f = fixture(which);
  FclFixture fcl;
  fcl.parts = fcl_parts(f.scene);
  collision::DetectorOptions options;
  options.tolerance = 1e-3;
  collision::SpacetimeDetector detector(f.transition, options);
  detector.detect(f.scene, f.trees);
  fcl.engine_groups = detector.groups();
  fcl.guaranteed = guaranteed_samples(f.scene, f.transition, options.tolerance);
  fcl.time_tolerance = 1.0 / static_cast<double>(fcl.guaranteed.times.size() - 1);
  return cache.emplace(which, std::move(fcl)).first->second;
}

/// FCL discrete collision at each of `times`, parallel over them like the engine and the
/// reference check. Counters: samples with a collision, (sample, pair) hits, and how many of
/// those no engine interval of the same pair covers within `slack` in time (misses).
void fcl_discrete(benchmark::State& state, const Fixture& f, const FclFixture& fcl, const std::vector<double>& times,
                  bool all_contacts, double slack) {
  const int samples = static_cast<int>(times.size());
  std::vector<FclSample> hits(samples);
  for (auto _ : state) {
    tbb::parallel_for(0, samples, [&](int s) { hits[s] = fcl_sample(f.scene, f.transition, fcl.parts, times[s], all_contacts); });
    benchmark::DoNotOptimize(hits.data());
  }
  long colliding_samples = 0, pair_hits = 0, missed = 0, triangle_pairs = 0;
  for (int s = 0; s < samples; ++s) {
    colliding_samples += hits[s].pairs.empty() ? 0 : 1;
    triangle_pairs += hits[s].triangle_pairs;
    for (const auto& [a, b] : hits[s].pairs) {
      ++pair_hits;
      const double t = times[s];
      const bool covered = std::any_of(fcl.engine_groups.begin(), fcl.engine_groups.end(), [&](const auto& g) {
        return g.parts[0] == a && g.parts[1] == b && g.t0 <= t + slack && t - slack <= g.t1;
      });
      missed += covered ? 0 : 1;
    }
  }
  describe(state, f);
  state.counters["fcl_samples"] = samples;
  state.counters["colliding_samples"] = static_cast<double>(colliding_samples);
  state.counters["pair_hits"] = static_cast<double>(pair_hits);
  state.counters["missed_by_engine"] = static_cast<double>(missed);
  if (all_contacts) state.counters["triangle_pairs"] = static_cast<double>(triangle_pairs);
}

/// FCL's yes/no answer per pair of parts at each of the engine's ~33 proxy sample times: the
/// same time resolution, but no guarantee between the samples.
void BM_FclPerStep(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  fcl_discrete(state, fixture(which), fcl_fixture(which), fixture(which).sample_times, false, 1e-9);
}

/// The same, asked for every intersecting triangle pair (closer to what the engine computes).
void BM_FclAllContactsPerStep(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  fcl_discrete(state, fixture(which), fcl_fixture(which), fixture(which).sample_times, true, 1e-9);
}

/// FCL at the engine's guarantee: discrete collision at a uniform step so small that no vertex
/// moves more than the tolerance (1 mm) between two samples (`guaranteed_samples`), whether
/// each pair intersects (all:0) or every intersecting triangle pair (all:1).
void BM_FclGuaranteedStep(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const FclFixture& fcl = fcl_fixture(which);
  fcl_discrete(state, fixture(which), fcl, fcl.guaranteed.times, state.range(1) != 0, fcl.time_tolerance);
  state.counters["max_displacement"] = fcl.guaranteed.max_displacement;
}

/// FCL's continuous collision per pair of parts over each of the engine's proxy steps (screw
/// motion between the step's end poses, conservative advancement): the first contact of each
/// step, compared with the engine's intervals.
void BM_FclContinuous(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const Fixture& f = fixture(which);
  const FclFixture& fcl = fcl_fixture(which);
  FclCcdResult result;
  for (auto _ : state) {
    result = fcl_ccd_first_contacts(f.scene, f.transition, fcl.parts, f.sample_times);
    benchmark::DoNotOptimize(result.contacts.data());
  }
  const CcdComparison c = compare_with_engine(result.contacts, fcl.engine_groups, fcl.time_tolerance);
  describe(state, f);
  state.counters["pair_steps"] = static_cast<double>(result.pair_steps);
  state.counters["first_contacts"] = static_cast<double>(result.contacts.size());
  state.counters["engine_intervals"] = c.intervals;
  state.counters["starts_found"] = c.starts_found;
  state.counters["starts_missed"] = c.starts_missed;
  state.counters["intervals_missed"] = c.intervals_missed;
  state.counters["ends_unreported"] = c.ends_unreported;
  state.counters["extra_contacts"] = c.extra_contacts;
  state.counters["pairs"] = c.pairs;
  state.counters["pairs_missed"] = c.pairs_missed;
  state.counters["first_contact_error"] = c.first_contact_error;
  state.counters["time_tolerance"] = fcl.time_tolerance;
}

BENCHMARK(BM_FclPerStep)
    ->ArgsProduct({{kElephant, kBunnyArmadillo, kEight, kKitchenHasty, kKitchen}})
    ->ArgName("scene")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FclPerStep)->Arg(kGallery)->ArgName("scene")->Unit(benchmark::kMillisecond)->UseRealTime()
    ->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK(BM_FclAllContactsPerStep)
    ->ArgsProduct({{kElephant, kBunnyArmadillo, kEight, kKitchenHasty, kKitchen}})
    ->ArgName("scene")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FclAllContactsPerStep)
    ->Arg(kGallery)
    ->ArgName("scene")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime()
    ->Iterations(1);
// Thousands of samples: the slow scenes run once per measurement. The gallery only asks
// whether the parts intersect (every contact at ~15 K samples of 1 M triangles takes minutes).
BENCHMARK(BM_FclGuaranteedStep)
    ->ArgsProduct({{kElephant, kEight, kKitchenHasty, kKitchen}, {0, 1}})
    ->ArgNames({"scene", "all"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FclGuaranteedStep)
    ->ArgsProduct({{kBunnyArmadillo}, {0, 1}})
    ->ArgNames({"scene", "all"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime()
    ->Iterations(1);
BENCHMARK(BM_FclGuaranteedStep)->Args({kGallery, 0})->ArgNames({"scene", "all"})->Unit(benchmark::kMillisecond)->UseRealTime()
    ->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK(BM_FclContinuous)
    ->ArgsProduct({{kElephant, kBunnyArmadillo, kEight, kKitchenHasty, kKitchen}})
    ->ArgName("scene")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FclContinuous)->Arg(kGallery)->ArgName("scene")->Unit(benchmark::kMillisecond)->UseRealTime()
    ->MeasureProcessCPUTime()->Iterations(1);
#endif

}  // namespace

BENCHMARK_MAIN();
