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
// whether each pair of parts intersects (BM_FclPerStep, the baseline of the issue), and for every
// intersecting triangle pair (BM_FclAllContactsPerStep, the engine's and the reference's output).
// Every benchmark reports wall-clock time ("Time") and the whole process's CPU time over all its
// threads ("CPU"), which the virtual machine's steal time does not inflate.

#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <filesystem>
#include <map>
#include <memory>
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
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
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
/// FCL 0.7's own BVHs (BVHModel<OBBRSS>, built once per part) and the engine's result, per scene.
struct FclModels {
  std::vector<std::shared_ptr<fcl::CollisionGeometryd>> geometry;
  std::vector<collision::CollisionInterval> engine_groups;  ///< 28-DOP, 1 mm: for the miss count
};

const FclModels& fcl_models(int which) {
  static std::map<int, FclModels> cache;
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  auto it = cache.find(which);
  if (it != cache.end()) return it->second;
  const Fixture& f = fixture(which);
  FclModels models;
  for (const auto& part : f.scene.parts) {
    std::vector<fcl::Vector3d> vertices;
    std::vector<fcl::Triangle> triangles;
    for (int v = 0; v < part.mesh.V.rows(); ++v) vertices.emplace_back(part.mesh.V.row(v).transpose());
    for (int t = 0; t < part.mesh.F.rows(); ++t) triangles.emplace_back(part.mesh.F(t, 0), part.mesh.F(t, 1), part.mesh.F(t, 2));
    auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(vertices.size()));
    model->addSubModel(vertices, triangles);
    model->endModel();
    model->computeLocalAABB();
    models.geometry.push_back(std::move(model));
  }
  collision::SpacetimeDetector detector(f.transition, {});
  detector.detect(f.scene, f.trees);
  models.engine_groups = detector.groups();
  return cache.emplace(which, std::move(models)).first->second;
}

/// What FCL finds at one time: the intersecting pairs of parts, and their triangle pairs.
struct FclSample {
  std::vector<std::pair<int, int>> pairs;
  long triangle_pairs = 0;
};

/// Every pair of parts that FCL finds intersecting at time t: a broad phase over the parts'
/// AABBs (DynamicAABBTree), then FCL's BVH test, which stops at the first intersecting triangle
/// pair, or with `all_contacts` goes on to every intersecting triangle pair (what the engine
/// reports over time, and what the reference check reports per sample).
FclSample fcl_sample(const Fixture& f, const FclModels& models, double t, bool all_contacts) {
  const int n = static_cast<int>(f.scene.parts.size());
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  fcl::DynamicAABBTreeCollisionManagerd manager;
  for (int p = 0; p < n; ++p) {
    const motion::Pose pose = f.scene.pose_at(f.transition, p, t);
    const Eigen::Isometry3d M = pose.to_isometry(f.scene.parts[p].center);
    auto object = std::make_unique<fcl::CollisionObjectd>(models.geometry[p], M.linear(), M.translation());
    object->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(p)));
    manager.registerObject(object.get());
    objects.push_back(std::move(object));
  }
  manager.setup();
  struct Data {
    FclSample sample;
    bool all_contacts;
  } data{{}, all_contacts};
  manager.collide(&data, [](fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* user) {
    auto& d = *static_cast<Data*>(user);
    fcl::CollisionRequestd request;  // default: one contact, i.e. whether they intersect
    if (d.all_contacts) request.num_max_contacts = std::numeric_limits<int>::max();
    fcl::CollisionResultd result;
    if (fcl::collide(o1, o2, request, result) > 0) {
      const int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
      const int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
      d.sample.pairs.emplace_back(std::min(a, b), std::max(a, b));
      d.sample.triangle_pairs += static_cast<long>(result.numContacts());
    }
    return false;  // go on: every colliding pair
  });
  std::sort(data.sample.pairs.begin(), data.sample.pairs.end());
  return data.sample;
}

/// FCL discrete collision at every one of the engine's proxy sample times, parallel over the
/// samples like the engine and the reference check. Counters: samples with a collision, (sample,
/// pair) hits, and how many of those no engine contact of the same pair covers (misses).
void fcl_per_step(benchmark::State& state, bool all_contacts) {
  const int which = static_cast<int>(state.range(0));
  const Fixture& f = fixture(which);
  const FclModels& models = fcl_models(which);
  const int samples = static_cast<int>(f.sample_times.size());
  std::vector<FclSample> hits(samples);
  for (auto _ : state) {
    tbb::parallel_for(0, samples, [&](int s) { hits[s] = fcl_sample(f, models, f.sample_times[s], all_contacts); });
    benchmark::DoNotOptimize(hits.data());
  }
  long colliding_samples = 0, pair_hits = 0, missed = 0, triangle_pairs = 0;
  for (int s = 0; s < samples; ++s) {
    colliding_samples += hits[s].pairs.empty() ? 0 : 1;
    triangle_pairs += hits[s].triangle_pairs;
    for (const auto& [a, b] : hits[s].pairs) {
      ++pair_hits;
      const double t = f.sample_times[s];
      const bool covered = std::any_of(models.engine_groups.begin(), models.engine_groups.end(), [&](const auto& g) {
        return g.parts[0] == a && g.parts[1] == b && g.t0 <= t + 1e-9 && t - 1e-9 <= g.t1;
      });
      missed += covered ? 0 : 1;
    }
  }
  describe(state, f);
  state.counters["colliding_samples"] = static_cast<double>(colliding_samples);
  state.counters["pair_hits"] = static_cast<double>(pair_hits);
  state.counters["missed_by_engine"] = static_cast<double>(missed);
  if (all_contacts) state.counters["triangle_pairs"] = static_cast<double>(triangle_pairs);
}

/// The baseline: FCL's yes/no answer per pair of parts at every sample time.
void BM_FclPerStep(benchmark::State& state) { fcl_per_step(state, false); }

/// FCL asked for every intersecting triangle pair at every sample time (closer to what the
/// engine computes: all contacts, for the collision boxes).
void BM_FclAllContactsPerStep(benchmark::State& state) { fcl_per_step(state, true); }

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
#endif

}  // namespace

BENCHMARK_MAIN();
