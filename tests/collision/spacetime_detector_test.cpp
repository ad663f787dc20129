#include "reconfig/collision/spacetime_detector.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <random>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

#include "reconfig/collision/consolidate.h"
#include "reconfig/collision/contact_tolerance.h"
#include "reconfig/collision/triangle_touching.h"
#include "reconfig/collision/frame_grid.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/collision/triangle_pair_ccd.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/history.h"
#include "reconfig/scene/scene_file.h"
#include "support/random_scene.h"
#include "support/test_data.h"

namespace reconfig::collision {
namespace {

/// Random scenes spread out enough that parts meet now and then rather than all the time.
scene::Reconfigurable random_scene(std::uint32_t seed) {
  testing::RandomSceneOptions options;
  options.spread = 1.5;
  return testing::random_scene(seed, options);
}

struct Detected {
  std::vector<TriangleContact> contacts;
  std::vector<CollisionInterval> groups;
  std::vector<Containment> containments;
  std::vector<CollisionInterval> intervals;
  DetectionStats stats;
};

Detected detect(const scene::Reconfigurable& scene, DetectorOptions options) {
  SpacetimeDetector detector(0, options);
  EXPECT_TRUE(detector.detect(scene, build_body_trees(scene)));
  return {detector.contacts(), detector.groups(), detector.containments(),
          consolidate(detector.groups(), detector.containments()), detector.last_stats()};
}

/// Whether two lists of groups say exactly the same: when, where, which parts.
::testing::AssertionResult same_groups(const std::vector<CollisionInterval>& x, const std::vector<CollisionInterval>& y) {
  if (x.size() != y.size()) return ::testing::AssertionFailure() << x.size() << " groups against " << y.size();
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i].t0 != y[i].t0 || x[i].t1 != y[i].t1 || x[i].parts != y[i].parts || x[i].possible != y[i].possible ||
        x[i].box.min() != y[i].box.min() || x[i].box.max() != y[i].box.max())
      return ::testing::AssertionFailure() << "group " << i << ": [" << x[i].t0 << ", " << x[i].t1 << "] "
                                           << x[i].box.min().transpose() << " / " << x[i].box.max().transpose()
                                           << (x[i].possible ? " possible" : "") << " against [" << y[i].t0 << ", "
                                           << y[i].t1 << "] " << y[i].box.min().transpose() << " / "
                                           << y[i].box.max().transpose() << (y[i].possible ? " possible" : "");
  return ::testing::AssertionSuccess();
}

/// Whether some interval of `intervals` for parts {a, b} covers time t (with slack).
bool covered(const std::vector<CollisionInterval>& intervals, int a, int b, double t, double slack) {
  for (const CollisionInterval& ci : intervals)
    if (std::find(ci.parts.begin(), ci.parts.end(), a) != ci.parts.end() &&
        std::find(ci.parts.begin(), ci.parts.end(), b) != ci.parts.end() && t >= ci.t0 - slack && t <= ci.t1 + slack)
      return true;
  return false;
}

/// Conservative mode never misses a collision of the true motion: every colliding sample of the
/// reference check (dense sampling of the exact motion, exact static tests) lies inside an
/// engine interval.
TEST(SpacetimeDetector, ConservativeModeMissesNoReferenceCollision) {
  int colliding_samples = 0;
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    const scene::Reconfigurable scene = random_scene(seed);
    DetectorOptions options;
    options.tolerance = 2e-3;
    options.conservative = true;
    const Detected engine = detect(scene, options);
    ReferenceCheckRequest request;
    request.samples = 201;
    const ReferenceCheckResult reference = reference_check(scene, request);
    for (const SampleContact& c : reference.contacts[0]) {
      ++colliding_samples;
      EXPECT_TRUE(covered(engine.intervals, c.part_a, c.part_b, sample_time(c.sample, request.samples), 0))
          << "seed " << seed << " sample " << c.sample << " parts " << c.part_a << "," << c.part_b;
    }
  }
  EXPECT_GT(colliding_samples, 50);  // the scenes do collide
}

/// Without inflation the engine tests the proxies (within `tolerance` of the true motion):
/// a reference collision may be missed only at the very ends of an interval, where the
/// penetration is shallower than the tolerance.
TEST(SpacetimeDetector, ExactModeAgreesWithTheReferenceUpToTheProxyTolerance) {
  for (std::uint32_t seed = 20; seed < 30; ++seed) {
    const scene::Reconfigurable scene = random_scene(seed);
    DetectorOptions options;
    options.tolerance = 2e-4;
    const Detected engine = detect(scene, options);
    ReferenceCheckRequest request;
    request.samples = 201;
    const ReferenceCheckResult reference = reference_check(scene, request);
    for (const SampleContact& c : reference.contacts[0])
      EXPECT_TRUE(covered(engine.intervals, c.part_a, c.part_b, sample_time(c.sample, request.samples), 0.01))
          << "seed " << seed << " t " << sample_time(c.sample, request.samples);
    // Every engine interval holds a real collision: the reference sees the same parts collide
    // in it, or it is shorter than the sampling can see.
    for (const CollisionInterval& ci : engine.intervals) {
      if (ci.duration() < 0.02) continue;
      bool seen = false;
      for (int i = 0; i <= 20 && !seen; ++i) {
        const double t = ci.t0 + (ci.t1 - ci.t0) * i / 20.0;
        for (const SampleContact& c : reference.contacts[0])
          if (std::abs(sample_time(c.sample, request.samples) - t) <= 0.5 / (request.samples - 1) &&
              std::find(ci.parts.begin(), ci.parts.end(), c.part_a) != ci.parts.end() &&
              std::find(ci.parts.begin(), ci.parts.end(), c.part_b) != ci.parts.end())
            seen = true;
      }
      EXPECT_TRUE(seen) << "seed " << seed << " engine interval [" << ci.t0 << ", " << ci.t1 << "]";
    }
  }
}

/// The three axis families bound differently but must find exactly the same contacts (all of
/// them), and the same groups when the search stops early.
TEST(SpacetimeDetector, DopFamiliesFindTheSameContacts) {
  for (std::uint32_t seed = 40; seed < 44; ++seed) {
    const scene::Reconfigurable scene = random_scene(seed);
    std::vector<std::vector<TriangleContact>> results;
    std::vector<std::vector<CollisionInterval>> groups;
    for (DopFamily family : {DopFamily::k8, DopFamily::k28, DopFamily::k80}) {
      DetectorOptions options;
      options.dop = family;
      groups.push_back(detect(scene, options).groups);
      options.all_contacts = true;
      results.push_back(detect(scene, options).contacts);
    }
    EXPECT_TRUE(same_groups(groups[0], groups[1])) << seed;
    EXPECT_TRUE(same_groups(groups[0], groups[2])) << seed;
    ASSERT_EQ(results[0].size(), results[1].size()) << seed;
    ASSERT_EQ(results[0].size(), results[2].size()) << seed;
    for (std::size_t i = 0; i < results[0].size(); ++i)
      for (int k : {1, 2}) {
        EXPECT_EQ(results[0][i].triangle_a, results[k][i].triangle_a);
        EXPECT_EQ(results[0][i].triangle_b, results[k][i].triangle_b);
        EXPECT_EQ(results[0][i].t0, results[k][i].t0);
        EXPECT_EQ(results[0][i].t1, results[k][i].t1);
      }
  }
}


/// After edits (and after undoing them), the incremental update gives exactly the groups of a
/// detection from scratch.
TEST(SpacetimeDetector, IncrementalUpdateEqualsDetectionFromScratch) {
  std::mt19937 random(5);
  for (std::uint32_t seed = 60; seed < 66; ++seed) {
    scene::Reconfigurable scene = random_scene(seed);
    const BodyTrees trees = build_body_trees(scene);
    SpacetimeDetector incremental(0, {});
    ASSERT_TRUE(incremental.detect(scene, trees));
    scene::History history;
    for (int step = 0; step < 4; ++step) {
      const std::string part = "part" + std::to_string(random() % 3);
      const double t = 0.1 + 0.8 * (random() % 1000) / 1000.0;
      scene::DirtySet dirty = history.execute(scene, scene::insert_key("move", part, scene::KeyKind::kTranslation, t));
      ASSERT_TRUE(incremental.update(scene, trees, dirty));
      // Move the new key: the part's motion changes around t only.
      const auto& keys = std::get<scene::KeyframedTrack>(scene.transitions[0].tracks.at(part)).translation;
      int key = 0;
      while (keys[key].time != t) ++key;
      motion::TranslationKey moved = keys[key];
      const Eigen::Vector3d shift = Eigen::Vector3d::Random() * 0.3;
      moved.point += shift;
      moved.in += shift;
      moved.out += shift;
      dirty = history.execute(scene, scene::set_translation_key("move", part, key, moved));
      ASSERT_TRUE(incremental.update(scene, trees, dirty));

      SpacetimeDetector fresh(0, {});
      ASSERT_TRUE(fresh.detect(scene, trees));
      EXPECT_TRUE(same_groups(incremental.groups(), fresh.groups())) << "seed " << seed << " step " << step;
      EXPECT_EQ(incremental.containments().size(), fresh.containments().size());
      // And undoing brings back exactly the original proxies' answer for that range.
      if (step == 3) {
        while (history.can_undo()) ASSERT_TRUE(incremental.update(scene, trees, history.undo(scene)));
        SpacetimeDetector original(0, {});
        ASSERT_TRUE(original.detect(scene, trees));
        EXPECT_TRUE(same_groups(incremental.groups(), original.groups()));
      }
    }
  }
}

/// Whether no contact appears twice in a list sorted by `contacts()`'s order (a triangle pair
/// whose narrow phase runs first, from a hint, may be reached again by the search).
::testing::AssertionResult each_once(const std::vector<TriangleContact>& contacts) {
  const auto fields = [](const TriangleContact& c) {
    return std::tuple(c.t0, c.t1, c.part_a, c.part_b, c.triangle_a, c.triangle_b, c.step_t0, c.box.min().x(), c.box.max().x());
  };
  for (std::size_t i = 1; i < contacts.size(); ++i)
    if (fields(contacts[i - 1]) == fields(contacts[i])) return ::testing::AssertionFailure() << "contact " << i << " reported twice";
  return ::testing::AssertionSuccess();
}

/// A sphere sweeping straight through a still one (their surfaces cross over most of the
/// transition), both of 1,280 triangles.
scene::Reconfigurable sweep_through_scene() {
  scene::Reconfigurable scene;
  scene.states = {{"start", {}}, {"end", {}}};
  scene::Transition transition{"move", "start", "end", true, {}};
  for (const std::string name : {"still", "sweep"}) {
    scene::Part part;
    part.name = name;
    part.source = scene::SpherePrimitive{0.5};
    part.mesh = geometry::make_sphere(0.5, 3);
    part.center = scene::part_center(part.mesh);
    scene.parts.push_back(part);
  }
  const motion::Pose still{Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero()};
  const Eigen::Vector3d a(-0.8, 0.1, 0), b(0.8, -0.1, 0.05);
  scene::KeyframedTrack track;
  track.translation = {{0.0, a, a, a + Eigen::Vector3d(0.3, 0.2, 0)}, {1.0, b, b - Eigen::Vector3d(0.3, -0.2, 0), b}};
  track.rotation = {{0.0, Eigen::Quaterniond::Identity()}, {1.0, Eigen::Quaterniond(Eigen::AngleAxisd(1.5, Eigen::Vector3d::UnitY()))}};
  transition.tracks["sweep"] = track;
  scene.states[0].poses = {{"still", still}, {"sweep", {Eigen::Quaterniond::Identity(), a}}};
  scene.states[1].poses = {{"still", still}, {"sweep", {track.rotation.back().rotation, b}}};
  scene.transitions.push_back(transition);
  return scene;
}

/// An update starts from the triangle pairs that made the previous groups' extents: after a
/// 1 mm edit of the middle key (which changes the motion over the whole transition), it
/// reaches the groups of a detection from scratch (exactly) with less work (a fifth less here), and reports no
/// contact twice.
TEST(SpacetimeDetector, UpdateStartsFromThePreviousExtents) {
  scene::Reconfigurable scene = sweep_through_scene();
  const BodyTrees trees = build_body_trees(scene);
  SpacetimeDetector incremental(0, {});
  ASSERT_TRUE(incremental.detect(scene, trees));
  ASSERT_GT(incremental.groups().size(), 20u);
  scene::History history;
  ASSERT_TRUE(incremental.update(scene, trees, history.execute(scene, scene::insert_key("move", "sweep", scene::KeyKind::kTranslation, 0.5))));
  for (int edit = 0; edit < 3; ++edit) {
    motion::TranslationKey key = std::get<scene::KeyframedTrack>(scene.transitions[0].tracks.at("sweep")).translation[1];
    const Eigen::Vector3d shift(0, 0, edit % 2 == 0 ? 0.001 : -0.0005);
    key.point += shift;
    key.in += shift;
    key.out += shift;
    ASSERT_TRUE(incremental.update(scene, trees, history.execute(scene, scene::set_translation_key("move", "sweep", 1, key))));
    SpacetimeDetector fresh(0, {});
    ASSERT_TRUE(fresh.detect(scene, trees));
    EXPECT_TRUE(same_groups(incremental.groups(), fresh.groups())) << "edit " << edit;
    // The update traversed the whole transition again.
    EXPECT_LT(incremental.last_stats().bound_tests, 0.9 * fresh.last_stats().bound_tests) << "edit " << edit;
    EXPECT_TRUE(each_once(incremental.contacts())) << "edit " << edit;
  }
}

/// Odd proxy steps start from the triangle pairs that made their neighbors' extents; when the
/// search reaches those pairs again, their contacts are not reported twice.
TEST(SpacetimeDetector, NoContactIsReportedTwice) {
  for (std::uint32_t seed = 120; seed < 126; ++seed) {
    testing::RandomSceneOptions scene_options;
    scene_options.spread = 0.3;  // parts overlap most of the time
    scene_options.sphere_subdivisions = 2;
    const Detected result = detect(testing::random_scene(seed, scene_options), {});
    EXPECT_GT(result.contacts.size(), 10u) << "seed " << seed;
    EXPECT_TRUE(each_once(result.contacts)) << "seed " << seed;
  }
  EXPECT_TRUE(each_once(detect(sweep_through_scene(), {}).contacts));
}

/// The traversal (k-DOP pruning, time splitting, and the culling of leaf pairs whose k-DOPs
/// meet in no piece of the step) loses nothing: the narrow phase run on every triangle pair at
/// every step of the merged proxy samples finds no intersection the detector does not report.
TEST(SpacetimeDetector, TraversalLosesNoContactOfTheNarrowPhase) {
  int checked = 0;
  for (std::uint32_t seed = 80; seed < 83; ++seed) {
    testing::RandomSceneOptions scene_options;
    scene_options.parts = 3;
    scene_options.spread = 0.6;
    const scene::Reconfigurable scene = testing::random_scene(seed, scene_options);
    DetectorOptions options;
    options.all_contacts = true;
    SpacetimeDetector detector(0, options);
    ASSERT_TRUE(detector.detect(scene, build_body_trees(scene)));
    const auto& proxies = detector.proxies();
    const auto posed = [&](int part, int triangle, double t) {
      const PartProxy& proxy = proxies[part];
      const int k = proxy.step_of(t);
      const double s = std::clamp((t - proxy.times[k]) / (proxy.times[k + 1] - proxy.times[k]), 0.0, 1.0);
      const geometry::Mesh& mesh = scene.parts[part].mesh;
      std::array<Eigen::Vector3d, 3> corners;
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector3d v = mesh.V.row(mesh.F(triangle, c));
        corners[c] = (1 - s) * (proxy.poses[k] * v) + s * (proxy.poses[k + 1] * v);
      }
      return corners;
    };
    const int n = static_cast<int>(scene.parts.size());
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        std::vector<double> times = proxies[a].times;
        times.insert(times.end(), proxies[b].times.begin(), proxies[b].times.end());
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        for (std::size_t k = 0; k + 1 < times.size(); ++k)
          for (int ta = 0; ta < scene.parts[a].mesh.face_count(); ++ta)
            for (int tb = 0; tb < scene.parts[b].mesh.face_count(); ++tb) {
              TrianglePairCcdRequest request;
              request.a_start = posed(a, ta, times[k]);
              request.a_end = posed(a, ta, times[k + 1]);
              request.b_start = posed(b, tb, times[k]);
              request.b_end = posed(b, tb, times[k + 1]);
              request.time_tolerance = 1.0 / 32;
              request.distance_tolerance = 1e-4;
              request.merge_pieces = false;  // as the traversal asks
              // What interferes beyond δ of what the narrow phase finds (step parameters).
              const std::vector<TimeInterval> spans =
                  interference_pieces(request.a_start, request.a_end, request.b_start, request.b_end,
                                      triangle_pair_ccd(request).intervals, contact_tolerance(scene, 0));
              for (const TimeInterval& span : spans) {
                ++checked;
                const double t = times[k] + 0.5 * (span.lo + span.hi) * (times[k + 1] - times[k]);
                const bool reported = std::any_of(detector.contacts().begin(), detector.contacts().end(), [&](const TriangleContact& c) {
                  return c.part_a == a && c.part_b == b && c.triangle_a == ta && c.triangle_b == tb &&
                         c.t0 - 1e-9 <= t && t <= c.t1 + 1e-9;
                });
                EXPECT_TRUE(reported) << "seed " << seed << " parts " << a << "," << b << " triangles " << ta << ","
                                      << tb << " t " << t;
              }
            }
      }
  }
  EXPECT_GT(checked, 100);
}

/// Stopping early loses nothing: the groups (time extents, boxes, parts, `possible`) are
/// exactly those built from every contact, in exact and conservative mode, with exact and
/// rounded boxes, on scenes from grazing to deep overlaps; and stopping early does skip work,
/// and finds only triangle pairs that every contact has.
TEST(SpacetimeDetector, StoppingEarlyGivesTheGroupsOfAllContacts) {
  long pruned = 0, contacts = 0, all = 0;
  for (std::uint32_t seed = 100; seed < 112; ++seed)
    for (const bool conservative : {false, true}) {
      testing::RandomSceneOptions scene_options;
      scene_options.spread = seed % 3 == 0 ? 0.3 : 0.8;  // some scenes overlap deeply all the time
      scene_options.sphere_subdivisions = seed % 2 == 0 ? 2 : 1;
      const scene::Reconfigurable scene = testing::random_scene(seed, scene_options);
      DetectorOptions options;
      options.conservative = conservative;
      options.frame = seed % 4 == 1 ? 0.05 : 0.01;
      options.breadth_first_items = seed % 2 == 0 ? 8 : 8192;  // depth first early, or mostly breadth first
      options.box_resolution = seed % 3 == 1 ? 0.0 : seed % 3 == 2 ? 0.02 : 0.1;  // exact boxes, or rounded
      const Detected early = detect(scene, options);
      options.all_contacts = true;
      const Detected every = detect(scene, options);
      EXPECT_TRUE(same_groups(early.groups, every.groups)) << "seed " << seed << " conservative " << conservative;
      // Every triangle pair found early is one that every contact has (the contacts themselves
      // may be cut where the narrow phase skipped pieces inside a group).
      const auto pairs = [](const std::vector<TriangleContact>& found) {
        std::set<std::tuple<int, int, int, int, bool>> out;
        for (const TriangleContact& c : found) out.insert({c.part_a, c.triangle_a, c.part_b, c.triangle_b, c.possible});
        return out;
      };
      const auto early_pairs = pairs(early.contacts), every_pairs = pairs(every.contacts);
      EXPECT_TRUE(std::includes(every_pairs.begin(), every_pairs.end(), early_pairs.begin(), early_pairs.end()))
          << "seed " << seed << " conservative " << conservative;
      pruned += early.stats.pruned - every.stats.pruned;  // every contact: only work whose nodes meet in no frame
      contacts += static_cast<long>(early.contacts.size());
      all += static_cast<long>(every.contacts.size());
    }
  EXPECT_GT(pruned, 0);
  EXPECT_LT(contacts, all / 2) << "stopping early should find far fewer contacts";
}

/// The result does not depend on how many threads detect: the contacts (every field, in
/// order), groups, containments and work counts of one thread equal those of all cores, with
/// the breadth-first phase short or long (its levels run in parallel) and in both modes.
TEST(SpacetimeDetector, ResultsDoNotDependOnTheNumberOfThreads) {
  tbb::task_arena one_thread(1);
  int contacts = 0;
  for (std::uint32_t seed = 300; seed < 306; ++seed) {
    testing::RandomSceneOptions scene_options;
    scene_options.spread = seed % 2 == 0 ? 0.4 : 0.9;
    const scene::Reconfigurable scene = testing::random_scene(seed, scene_options);
    DetectorOptions options;
    options.conservative = seed % 3 == 0;
    options.breadth_first_items = seed % 2 == 0 ? 64 : 8192;
    Detected alone;
    one_thread.execute([&] { alone = detect(scene, options); });
    const Detected all = detect(scene, options);
    ASSERT_EQ(alone.contacts.size(), all.contacts.size()) << "seed " << seed;
    for (std::size_t i = 0; i < all.contacts.size(); ++i) {
      const TriangleContact &x = alone.contacts[i], &y = all.contacts[i];
      EXPECT_TRUE(x.part_a == y.part_a && x.triangle_a == y.triangle_a && x.part_b == y.part_b &&
                  x.triangle_b == y.triangle_b && x.t0 == y.t0 && x.t1 == y.t1 && x.box.min() == y.box.min() &&
                  x.box.max() == y.box.max() && x.possible == y.possible && x.step_t0 == y.step_t0 &&
                  x.step_t1 == y.step_t1)
          << "seed " << seed << " contact " << i;
    }
    EXPECT_TRUE(same_groups(alone.groups, all.groups)) << "seed " << seed;
    ASSERT_EQ(alone.containments.size(), all.containments.size()) << "seed " << seed;
    for (std::size_t i = 0; i < all.containments.size(); ++i)
      EXPECT_TRUE(alone.containments[i].inner == all.containments[i].inner &&
                  alone.containments[i].t0 == all.containments[i].t0 && alone.containments[i].t1 == all.containments[i].t1)
          << "seed " << seed;
    EXPECT_EQ(alone.stats.bound_tests, all.stats.bound_tests) << "seed " << seed;
    EXPECT_EQ(alone.stats.narrow_phase, all.stats.narrow_phase) << "seed " << seed;
    contacts += static_cast<int>(all.contacts.size());
  }
  EXPECT_GT(contacts, 50);  // the scenes collide enough for the comparison to mean something
}

/// Rounded boxes answer "where" to their resolution and never less: every group of exact
/// boxes lies within a group of rounded ones (same parts, its time extent and box inside),
/// every rounded group's time extent is exactly that of the exact groups it holds, and its box
/// reaches at most one grid cell beyond theirs, on grid planes.
TEST(SpacetimeDetector, RoundedBoxesHoldTheExactOnesWithinACell) {
  int groups = 0;
  for (std::uint32_t seed = 200; seed < 208; ++seed) {
    testing::RandomSceneOptions scene_options;
    scene_options.spread = seed % 2 == 0 ? 0.3 : 0.8;
    const scene::Reconfigurable scene = testing::random_scene(seed, scene_options);
    const BodyTrees trees = build_body_trees(scene);
    DetectorOptions options;
    options.box_resolution = 0;
    const Detected exact = detect(scene, options);
    options.box_resolution = 0.05;
    const Detected rounded = detect(scene, options);
    std::vector<std::vector<const CollisionInterval*>> held(rounded.groups.size());
    for (const CollisionInterval& e : exact.groups) {
      ++groups;
      int holders = 0;
      for (std::size_t r = 0; r < rounded.groups.size(); ++r) {
        const CollisionInterval& g = rounded.groups[r];
        if (g.parts == e.parts && g.t0 <= e.t0 && e.t1 <= g.t1 && g.box.contains(e.box) &&
            FrameGrid(options.frame).frame_of(0.5 * (g.t0 + g.t1)) == FrameGrid(options.frame).frame_of(0.5 * (e.t0 + e.t1))) {
          held[r].push_back(&e);
          ++holders;
        }
      }
      EXPECT_EQ(holders, 1) << "seed " << seed << " exact group [" << e.t0 << ", " << e.t1 << "]";
    }
    for (std::size_t r = 0; r < rounded.groups.size(); ++r) {
      const CollisionInterval& g = rounded.groups[r];
      ASSERT_FALSE(held[r].empty()) << "seed " << seed << ": a rounded group holds no exact group";
      double t0 = 1, t1 = 0;
      Eigen::AlignedBox3d hull;
      for (const CollisionInterval* e : held[r]) {
        t0 = std::min(t0, e->t0);
        t1 = std::max(t1, e->t1);
        hull.extend(e->box);
      }
      EXPECT_EQ(g.t0, t0);
      EXPECT_EQ(g.t1, t1);
      const double cell = options.box_resolution * std::min(2 * trees[g.parts[0]]->node(BodyTree::kRoot).half.norm(),
                                                            2 * trees[g.parts[1]]->node(BodyTree::kRoot).half.norm());
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(hull.min()[axis] - g.box.min()[axis], cell * (1 + 1e-9)) << "seed " << seed;
        EXPECT_LE(g.box.max()[axis] - hull.max()[axis], cell * (1 + 1e-9)) << "seed " << seed;
        for (const double plane : {g.box.min()[axis], g.box.max()[axis]})
          EXPECT_NEAR(plane / cell, std::round(plane / cell), 1e-6) << "seed " << seed << ": not on a grid plane";
      }
    }
  }
  EXPECT_GT(groups, 20);
}

/// A plank (2 m) drops through two posts 1.6 m apart that are one part: the two places where
/// it crosses them stay two intervals (they lie further apart than the grouping gap), each
/// with the box of its own crossing; posts 0.2 m apart (0.1 m between them, under 20 % of the
/// posts' size) make one interval.
TEST(SpacetimeDetector, SeparatePlacesOfOnePairStaySeparate) {
  for (const double apart : {1.6, 0.2}) {
    scene::Reconfigurable scene;
    scene::Part plank;
    plank.name = "plank";
    plank.source = scene::EditedMesh{};
    plank.mesh = geometry::make_box(Eigen::Vector3d(2.0, 0.1, 0.1));
    plank.center = scene::part_center(plank.mesh);
    scene::Part posts;
    posts.name = "posts";
    posts.source = scene::EditedMesh{};
    const geometry::Mesh post = geometry::make_box(Eigen::Vector3d(0.1, 0.1, 0.6));
    posts.mesh.V.resize(2 * post.V.rows(), 3);
    posts.mesh.F.resize(2 * post.F.rows(), 3);
    posts.mesh.V << post.V.rowwise() - Eigen::RowVector3d(apart / 2, 0, 0), post.V.rowwise() + Eigen::RowVector3d(apart / 2, 0, 0);
    posts.mesh.F << post.F, post.F.array() + static_cast<int>(post.V.rows());
    posts.center = scene::part_center(posts.mesh);
    scene.parts = {plank, posts};
    const Eigen::Vector3d high(0, 0, 1), low(0, 0, -1);
    const Eigen::Quaterniond still = Eigen::Quaterniond::Identity();
    scene.states = {{"start", {{"plank", {still, high}}, {"posts", {still, Eigen::Vector3d::Zero()}}}},
                    {"end", {{"plank", {still, low}}, {"posts", {still, Eigen::Vector3d::Zero()}}}}};
    scene::KeyframedTrack track;
    track.translation = {{0.0, high, high, high + (low - high) / 3}, {1.0, low, low + (high - low) / 3, low}};
    track.rotation = {{0.0, still}, {1.0, still}};
    scene.transitions = {{"drop", "start", "end", true, {{"plank", track}}}};

    DetectorOptions options;
    options.box_resolution = 0;  // exact boxes
    const Detected found = detect(scene, options);
    std::ostringstream listing;
    for (const CollisionInterval& ci : found.intervals)
      listing << "[" << ci.t0 << ", " << ci.t1 << "] " << ci.box.min().transpose() << " / " << ci.box.max().transpose() << "\n";
    SCOPED_TRACE(listing.str());
    if (apart > 1) {
      ASSERT_EQ(found.intervals.size(), 2u);
      for (const CollisionInterval& ci : found.intervals) {
        EXPECT_NEAR(std::abs(ci.box.center().x()), apart / 2, 0.01);
        EXPECT_LE(ci.box.sizes().x(), 0.1 + 1e-6);  // the post's width: where the surfaces cross
        // From when the plank's bottom reaches the posts' tops (z = 0.3) to when its top leaves
        // their bottoms (z = −0.3); it drops at a steady 2 m per unit of time.
        EXPECT_NEAR(ci.t0, 0.325, 0.01);
        EXPECT_NEAR(ci.t1, 0.675, 0.01);
      }
    } else {
      ASSERT_EQ(found.intervals.size(), 1u);
      EXPECT_NEAR(found.intervals[0].box.sizes().x(), apart + 0.1, 1e-6);
    }
  }
}

TEST(SpacetimeDetector, ProxiesStayWithinTolerance) {
  const scene::Reconfigurable scene = random_scene(3);
  for (double tolerance : {1e-2, 1e-3, 1e-4}) {
    for (int p = 0; p < 3; ++p) {
      const PartProxy proxy = build_part_proxy(scene, 0, p, tolerance);
      EXPECT_LE(proxy.deviation, tolerance);

      // Densely compare the proxy's vertex paths with the true motion.
      const auto& V = scene.parts[p].mesh.V;
      double worst = 0;
      for (int i = 0; i <= 2000; ++i) {
        const double t = i / 2000.0;
        const int k = proxy.step_of(t);
        const double s = (t - proxy.times[k]) / (proxy.times[k + 1] - proxy.times[k]);
        const Eigen::Isometry3d truth = scene.pose_at(0, p, t).to_isometry(scene.parts[p].center);
        for (int v = 0; v < V.rows(); v += 7) {
          const Eigen::Vector3d rest = V.row(v);
          const Eigen::Vector3d linear = (1 - s) * (proxy.poses[k] * rest) + s * (proxy.poses[k + 1] * rest);
          worst = std::max(worst, (linear - truth * rest).norm());
        }
      }
      EXPECT_LE(worst, tolerance * (1 + 1e-9)) << "part " << p;
      EXPECT_GT(worst, tolerance / 50) << "steps are not absurdly small";
    }
  }
}

TEST(SpacetimeDetector, ProxySamplesAreTheScenesPosesBitForBit) {
  // Keyframed tracks (random scenes), hinged doors (kitchen) and driven screw tracks with
  // hundreds of keys (the linkage walker): the proxy's poses are `Reconfigurable::pose_at`'s.
  std::vector<scene::Reconfigurable> scenes = {random_scene(3), random_scene(11)};
  for (const char* example : {"kitchen", "linkage-walker", "bench-table"})
    scenes.push_back(scene::load_scene(testing::source_dir() / "examples" / example / "scene.json"));
  int compared = 0;
  for (const scene::Reconfigurable& scene : scenes)
    for (int transition = 0; transition < static_cast<int>(scene.transitions.size()); ++transition)
      for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) {
        const PartProxy proxy = build_part_proxy(scene, transition, p, 1e-3);
        for (std::size_t k = 0; k < proxy.times.size(); ++k, ++compared) {
          const Eigen::Isometry3d truth = scene.pose_at(transition, p, proxy.times[k]).to_isometry(scene.parts[p].center);
          ASSERT_EQ(proxy.poses[k].matrix(), truth.matrix()) << "transition " << transition << ", part " << p << ", t = " << proxy.times[k];
        }
      }
  EXPECT_GT(compared, 1000);
}

/// The steps run in parallel and report from whichever thread finishes one: the callbacks
/// still come one at a time, in order, and returning false stops the detection.
TEST(SpacetimeDetector, CallbacksComeOneAtATimeAndCancellingStops) {
  const scene::Reconfigurable scene = random_scene(7);
  const BodyTrees trees = build_body_trees(scene);
  DetectorOptions options;
  options.breadth_first_items = 1;  // every step in the depth-first phase, from the start
  std::atomic<bool> inside = false;
  std::atomic<int> overlapping = 0, progress_calls = 0, previews = 0;
  double last = 0;
  bool ordered = true;
  const auto enter = [&] {
    if (inside.exchange(true)) ++overlapping;
    std::this_thread::sleep_for(std::chrono::microseconds(200));  // room for another thread to come in
  };
  DetectCallbacks callbacks;
  callbacks.progress = [&](double fraction) {
    enter();
    ordered = ordered && fraction >= last;
    last = fraction;
    ++progress_calls;
    inside = false;
    return true;
  };
  callbacks.preview = [&](const TraversalPreview&) {
    enter();
    ++previews;
    inside = false;
  };
  SpacetimeDetector detector(0, options);
  ASSERT_TRUE(detector.detect(scene, trees, callbacks));
  EXPECT_EQ(overlapping, 0);
  EXPECT_TRUE(ordered);
  EXPECT_EQ(last, 1.0);
  EXPECT_GE(previews, 2);  // the steps report in batches, and once all are done
  EXPECT_GE(progress_calls, 3);

  // Cancelled in the depth-first phase, it stops with no result; the next detection is whole.
  int refused = 0;
  DetectCallbacks cancelling;
  cancelling.progress = [&](double fraction) {
    if (fraction <= 0.5) return true;
    ++refused;
    return false;
  };
  EXPECT_FALSE(detector.detect(scene, trees, cancelling));
  EXPECT_EQ(refused, 1);  // asked no more once refused
  ASSERT_TRUE(detector.detect(scene, trees));
  SpacetimeDetector fresh(0, options);
  ASSERT_TRUE(fresh.detect(scene, trees));
  EXPECT_TRUE(same_groups(detector.groups(), fresh.groups()));
}

TEST(SpacetimeDetector, PreviewsNarrowDownToTheContacts) {
  const scene::Reconfigurable scene = random_scene(7);
  SpacetimeDetector detector(0, {});
  std::vector<TraversalPreview> previews;
  DetectCallbacks callbacks;
  callbacks.preview = [&](const TraversalPreview& p) { previews.push_back(p); };
  ASSERT_TRUE(detector.detect(scene, build_body_trees(scene), callbacks));
  ASSERT_GT(previews.size(), 3u);
  const auto total = [](const TraversalPreview& p) {
    double sum = 0;
    for (const auto& [a, b] : p.ranges) sum += b - a;
    return sum;
  };
  // Every contact lies in every preview (previews are conservative) ...
  for (const TraversalPreview& preview : previews)
    for (const TriangleContact& c : detector.contacts()) {
      bool inside = false;
      for (const auto& [a, b] : preview.ranges) inside = inside || (c.t0 >= a - 1e-12 && c.t1 <= b + 1e-12);
      EXPECT_TRUE(inside) << "level " << preview.level;
    }
  // ... and they shrink as the traversal goes deeper.
  EXPECT_LE(total(previews.back()), total(previews.front()));
}

}  // namespace
}  // namespace reconfig::collision
