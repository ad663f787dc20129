// Carving and the swept envelope in the studio, driven headless on the bench-table: the
// backrest carved by the armrests' sweep stops colliding in `unfold` (one undoable edit), a
// carve can be cancelled, bad requests change nothing, and the envelope of the selected part
// covers where it goes.

#include <gtest/gtest.h>

#include "reconfig/geometry/bounding_box.h"
#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/point_in_solid.h"
#include "reconfig/sweep/relative_motion.h"
#include "script.h"
#include "bench_table_unfold.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;

class StudioShaping : public BenchTableUnfold {
 protected:
  /// Carves the selected part by `settings` and waits: the time samples its sweeps took, from
  /// the status line ("carved P: volume A -> B (N time samples)"); −1 when it did not carve.
  int carve_and_count_time_samples(const ShapingPanel::CarveSettings& settings) {
    if (!studio().shaping().start_carve(studio(), settings)) return -1;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (studio().shaping().carving() && std::chrono::steady_clock::now() < deadline) frontend_->run_frame();
    frontend_->run_frame();
    const std::string& status = studio().status();
    const std::size_t open = status.rfind('(');
    if (status.rfind("carved ", 0) != 0 || open == std::string::npos) return -1;
    return std::stoi(status.substr(open + 1));
  }
};

TEST_F(StudioShaping, CarvingTheBackrestByTheArmrestsFreesUnfoldAndUndoRestoresIt) {
  ASSERT_EQ(intervals_shown(), 2u);  // the backrest hits both armrests
  const geometry::Mesh before = scene().parts[part("backrest")].mesh;
  run_script(*frontend_, "carve backrest by armrest_left,armrest_right offset 0.005\n"
                         "wait-collisions 60\n"
                         "expect-collisions 0\n"
                         "expect-status carved backrest\n", "carve.script");
  const geometry::Mesh& carved = scene().parts[part("backrest")].mesh;
  EXPECT_TRUE(geometry::check_mesh(carved).is_valid_solid());
  EXPECT_LT(geometry::mass_properties(carved).volume, geometry::mass_properties(before).volume);
  EXPECT_TRUE(studio().document()->modified());
  ASSERT_TRUE(studio().undo());  // one edit
  EXPECT_EQ(scene().parts[part("backrest")].mesh.V, before.V);
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  EXPECT_EQ(intervals_shown(), 2u);
}

TEST_F(StudioShaping, CarvingOverOneIntervalFreesThatPairAndLeavesTheOther) {
  studio().select_part(part("backrest"));
  studio().shaping().show_carve_window(studio());
  const std::vector<collision::CollisionInterval> intervals = studio().shaping().part_intervals(studio());
  ASSERT_EQ(intervals.size(), 2u);  // the backrest hits both armrests
  const collision::CollisionInterval chosen = intervals[0], other = intervals[1];
  const int carver = chosen.parts[0] == part("backrest") ? chosen.parts[1] : chosen.parts[0];
  studio().shaping().choose_interval(studio(), chosen);
  const ShapingPanel::CarveSettings settings = *studio().shaping().carve_window();
  EXPECT_EQ(settings.from, chosen.t0);
  EXPECT_EQ(settings.to, chosen.t1);
  EXPECT_EQ(settings.carvers, std::vector<std::string>{scene().parts[carver].name});
  const int samples = carve_and_count_time_samples(settings);
  ASSERT_TRUE(frontend_->run_until_collisions_current(milliseconds(60000)));
  ASSERT_EQ(intervals_shown(), 1u);  // only the pair not carved still collides
  const std::vector<collision::CollisionInterval> left = studio().shaping().part_intervals(studio());
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].parts, other.parts);
  // The same carver over the whole transition sweeps more of its motion.
  ASSERT_TRUE(studio().undo());
  ShapingPanel::CarveSettings whole = settings;
  whole.from = 0;
  whole.to = 1;
  EXPECT_LT(samples, carve_and_count_time_samples(whole));
}

TEST_F(StudioShaping, ATimeRangeOutsideTheTransitionIsRefused) {
  studio().select_part(part("backrest"));
  ShapingPanel::CarveSettings settings;
  settings.carvers = {"armrest_left"};
  settings.from = 0.6;
  settings.to = 0.4;
  EXPECT_FALSE(studio().shaping().start_carve(studio(), settings));
  EXPECT_NE(studio().status().find("time range"), std::string::npos) << studio().status();
  settings.from = 0;
  settings.to = 1.5;
  EXPECT_FALSE(studio().shaping().start_carve(studio(), settings));
  EXPECT_THROW(run_script(*frontend_, "carve-window backrest interval 5\n", "bad.script"), ScriptError);
}

TEST_F(StudioShaping, ACancelledCarveChangesNothing) {
  studio().select_part(part("backrest"));
  const std::uint64_t version = studio().document()->version();
  ShapingPanel::CarveSettings settings;
  settings.carvers = {"armrest_left", "armrest_right"};
  settings.grid = 0.002;  // fine: long enough to be cancelled while it runs
  ASSERT_TRUE(studio().shaping().start_carve(studio(), settings)) << studio().status();
  EXPECT_TRUE(studio().shaping().carving());
  EXPECT_FALSE(studio().shaping().start_carve(studio(), settings));  // one at a time
  frontend_->run_frame();  // the progress window with its Cancel button
  studio().shaping().cancel_carve(studio());
  EXPECT_FALSE(studio().shaping().carving());
  for (int i = 0; i < 3; ++i) frontend_->run_frame();
  EXPECT_EQ(studio().document()->version(), version);
  EXPECT_NE(studio().status().find("cancelled"), std::string::npos) << studio().status();
}

TEST_F(StudioShaping, BadCarveRequestsAreRefusedWithAReason) {
  studio().select_part(part("backrest"));
  ShapingPanel::CarveSettings settings;
  EXPECT_FALSE(studio().shaping().start_carve(studio(), settings));  // no carvers
  settings.carvers = {"no_such_part"};
  EXPECT_FALSE(studio().shaping().start_carve(studio(), settings));
  EXPECT_NE(studio().status().find("no_such_part"), std::string::npos) << studio().status();
  settings.carvers = {"backrest"};
  EXPECT_FALSE(studio().shaping().start_carve(studio(), settings));
  EXPECT_NE(studio().status().find("itself"), std::string::npos) << studio().status();
  EXPECT_THROW(run_script(*frontend_, "carve backrest armrest_left\n", "bad.script"), ScriptError);
  EXPECT_FALSE(studio().document()->modified());
}

TEST_F(StudioShaping, TheCarveWindowPresetsTheCollidingParts) {
  studio().select_part(part("backrest"));
  studio().shaping().show_carve_window(studio());
  frontend_->run_frame();
  const auto& window = studio().shaping().carve_window();
  ASSERT_TRUE(window);
  std::vector<std::string> carvers = window->carvers;
  std::sort(carvers.begin(), carvers.end());
  EXPECT_EQ(carvers, (std::vector<std::string>{"armrest_left", "armrest_right"}));
  studio().select_part(-1);  // nothing to carve: the window closes
  frontend_->run_frame();
  EXPECT_FALSE(studio().shaping().carve_window());
}

/// The Carve window previews what it would cut: the armrest's sweep in the backrest's frame,
/// shown while the window is open, holding the armrest wherever it is inside the backrest's box
/// at sampled times, recomputed when the settings change, gone when the window closes.
TEST_F(StudioShaping, TheCarveWindowPreviewsTheSweptVolumeInsideThePart) {
  const int backrest = part("backrest"), armrest = part("armrest_left");
  run_script(*frontend_, "carve-window backrest by armrest_left offset 0.005 grid 0.006\n"
                         "expect-carve-preview none\n"  // still sweeping
                         "wait-carve-preview 60\n"
                         "expect-carve-preview\n", "preview.script");
  const auto preview = studio().shaping().carve_preview(studio());
  ASSERT_TRUE(preview);
  EXPECT_TRUE(geometry::check_mesh(*preview).is_valid_solid());
  // Every armrest vertex at sampled times, in the backrest's frame, inside the backrest's box
  // (the preview is clipped to it), lies inside the preview.
  const sweep::RelativeMotion motion = sweep::relative_motion(scene(), unfold_, armrest, backrest);
  const Eigen::AlignedBox3d box = geometry::bounding_box(scene().parts[backrest].mesh.V);
  const geometry::Mesh& rest = scene().parts[armrest].mesh;
  // (The vertices and the faces' centroids: the armrest only grazes the backrest's box.)
  std::vector<Eigen::Vector3d> points;
  for (int v = 0; v < rest.vertex_count(); ++v) points.push_back(rest.V.row(v).transpose());
  for (int f = 0; f < rest.face_count(); ++f)
    points.push_back((rest.V.row(rest.F(f, 0)) + rest.V.row(rest.F(f, 1)) + rest.V.row(rest.F(f, 2))).transpose() / 3);
  int checked = 0;
  for (double t = 0; t <= 1.0; t += 1.0 / 64)
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector3d x = motion.at(t) * p;
      if (!box.contains(x)) continue;
      ++checked;
      ASSERT_TRUE(geometry::point_in_solid(*preview, x)) << "t " << t << " at " << p.transpose();
    }
  EXPECT_GT(checked, 20) << "the armrest passes through the backrest's box";
  // The viewport draws it (placed with the backrest): one more translucent mesh.
  EXPECT_NE(studio().shaping().overlay_revision(), 0u);
  // Both armrests: a new preview, holding the first.
  run_script(*frontend_, "carve-window backrest by armrest_left,armrest_right offset 0.005 grid 0.006\n"
                         "wait-carve-preview 60\n", "both.script");
  const auto both = studio().shaping().carve_preview(studio());
  ASSERT_TRUE(both);
  EXPECT_NE(both, preview);
  EXPECT_GT(both->face_count(), preview->face_count());
  // An edit of the design drops it until it is swept again; closing the window hides it.
  run_script(*frontend_, "sculpt armrest_left sphere 0.05 0.05 0.05 0.05 0 -0.25 0 translate 0 0.02 0\n", "edit.script");
  studio().select_part(backrest);
  EXPECT_FALSE(studio().shaping().carve_preview(studio()));
  studio().select_part(-1);  // the window closes
  frontend_->run_frame();
  EXPECT_FALSE(studio().shaping().carve_window());
  EXPECT_FALSE(studio().shaping().carve_preview(studio()));
}

TEST_F(StudioShaping, TheEnvelopeCoversThePartThroughoutTheTransitionAndFollowsEdits) {
  const int moving = part("backrest");  // it turns over in unfold
  studio().select_part(moving);
  run_script(*frontend_, "expect-envelope none\nenvelope on\nexpect-envelope\n", "envelope.script");
  const auto envelope = studio().shaping().envelope(studio());
  ASSERT_TRUE(envelope);
  Eigen::AlignedBox3d box = geometry::bounding_box(envelope->V);
  box.min().array() -= 1e-6;
  box.max().array() += 1e-6;
  for (double t = 0; t <= 1.0; t += 0.125) {
    const Eigen::MatrixX3d V = scene().posed_vertices(unfold_, moving, t);
    for (int v = 0; v < V.rows(); ++v) ASSERT_TRUE(box.contains(V.row(v).transpose())) << "t = " << t << ", vertex " << v;
  }
  // The part moves: its envelope reaches beyond where it is at any one time.
  const Eigen::AlignedBox3d start = geometry::bounding_box(scene().posed_vertices(unfold_, moving, 0.0));
  EXPECT_GT(box.volume(), 1.5 * start.volume());
  // An edit of the design gives a new envelope; off hides it.
  run_script(*frontend_, "sculpt armrest_left sphere 0.05 0.05 0.05 0.05 0 -0.25 0 translate 0 0.02 0\n", "edit.script");
  studio().select_part(moving);
  EXPECT_NE(studio().shaping().envelope(studio()), envelope);
  run_script(*frontend_, "envelope off\nexpect-envelope none\n", "off.script");
}

}  // namespace
}  // namespace reconfig::studio
