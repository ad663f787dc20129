#include "reconfig/linkage/linkage_edit.h"

#include <gtest/gtest.h>

#include <random>

#include "linkage_test_util.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace reconfig::linkage {
namespace {

// Central finite differences of the energy against its gradient.
void expect_gradient_matches(const Linkage& linkage, const EditObjectives& objectives, const std::string& what) {
  EditSettings settings;
  settings.samples = 24;
  const Eigen::Matrix2Xd X0 = linkage.initial_positions();
  Eigen::Matrix2Xd G;
  const double energy = edit_energy(linkage, objectives, settings, X0, &G);
  ASSERT_TRUE(std::isfinite(energy)) << what;
  const double h = 1e-6;
  double worst = 0, scale = 1e-8;
  for (Eigen::Index p = 0; p < X0.cols(); ++p)
    for (int c = 0; c < 2; ++c) {
      Eigen::Matrix2Xd plus = X0, minus = X0;
      plus(c, p) += h, minus(c, p) -= h;
      const double numeric = (edit_energy(linkage, objectives, settings, plus, nullptr) -
                              edit_energy(linkage, objectives, settings, minus, nullptr)) / (2 * h);
      worst = std::max(worst, std::abs(numeric - G(c, p)));
      scale = std::max(scale, std::abs(numeric));
    }
  EXPECT_LT(worst, 1e-5 * scale) << what << " (gradient scale " << scale << ")";
}

TEST(LinkageEdit, GradientMatchesFiniteDifferencesForEveryTerm) {
  const Linkage linkage = test::example("jansen.json");
  const int foot = linkage.find_joint("P"), knee = linkage.find_joint("F"), upper = linkage.find_joint("U");
  const auto angles = edit_sample_angles(linkage, 24);
  auto curve = joint_trajectory(linkage, foot, angles);
  for (auto& p : curve) p += Eigen::Vector2d(3, -2);

  EditObjectives drag;
  drag.drags.push_back({upper, linkage.joints[upper].position + Eigen::Vector2d(4, 1), std::nullopt, 1});
  drag.drags.push_back({knee, Eigen::Vector2d(-60, -40), 0.7, 2});
  drag.regularization_weight = 0.3;
  drag.reference_lengths = link_lengths(linkage);
  for (double& l : drag.reference_lengths) l *= 1.05;
  expect_gradient_matches(linkage, drag, "drags + regularization");

  EditObjectives track;
  track.trajectories.push_back({foot, curve, 2});
  expect_gradient_matches(linkage, track, "trajectory");

  EditObjectives box;
  box.envelope = EditObjectives::Envelope{Eigen::Vector2d(-85, -85), Eigen::Vector2d(10, 30), 1};
  expect_gradient_matches(linkage, box, "envelope");

  EditObjectives barrier;
  barrier.singularity_epsilon = 0.9;  // active on most triangles
  barrier.regularization_weight = 0;
  expect_gradient_matches(linkage, barrier, "singularity barrier");
}

TEST(LinkageEdit, DragMovesTheJointAndKeepsTheFootPath) {
  const Linkage linkage = test::example("jansen.json");
  const int upper = linkage.find_joint("U"), foot = linkage.find_joint("P");
  const auto angles = edit_sample_angles(linkage, 72);
  EditObjectives objectives;
  const Eigen::Vector2d target = linkage.joints[upper].position + Eigen::Vector2d(-5, 3);
  objectives.drags.push_back({upper, target, std::nullopt, 1});
  objectives.trajectories.push_back({foot, joint_trajectory(linkage, foot, angles), 10});
  const EditResult result = edit_linkage(linkage, objectives);
  EXPECT_LT(result.energy_after, result.energy_before);
  const double moved_before = (linkage.joints[upper].position - target).norm();
  const double moved_after = (result.linkage.joints[upper].position - target).norm();
  EXPECT_LT(moved_after, 0.5 * moved_before) << result.status;
  // The foot path changes by much less than the drag.
  const auto after = joint_trajectory(result.linkage, foot, angles);
  const auto before = joint_trajectory(linkage, foot, angles);
  double worst = 0;
  for (std::size_t s = 0; s < angles.size(); ++s) worst = std::max(worst, (after[s] - before[s]).norm());
  EXPECT_LT(worst, 1.5);
  EXPECT_TRUE(motion_range(SymbolicKinematics(result.linkage, order_joints(result.linkage))).full_rotation);
}

TEST(LinkageEdit, NeverBreaksTheLinkageEvenWhenDraggedIntoASingularity) {
  // Pull the crank pin B of a crank-rocker far out while holding A, D and C: a longer crank
  // soon violates Grashof's condition and the crank would lock. The edit must stop short:
  // the crank still turns fully, and it did get longer.
  std::mt19937 rng(99);
  for (int trial = 0; trial < 5; ++trial) {
    const Linkage linkage = test::random_crank_rocker(rng, 0.5 + trial);
    const Eigen::Vector2d A = linkage.joints[0].position, B = linkage.joints[2].position;
    EditObjectives objectives;
    for (int held : {0, 1, 3}) objectives.drags.push_back({held, linkage.joints[held].position, std::nullopt, 100});
    objectives.drags.push_back({2, A + 10 * (B - A).normalized(), std::nullopt, 1});
    objectives.regularization_weight = 0;
    objectives.singularity_weight = 1e-3;
    const EditResult result = edit_linkage(linkage, objectives);
    const Linkage& edited = result.linkage;
    EXPECT_TRUE(motion_range(SymbolicKinematics(edited, order_joints(edited))).full_rotation)
        << trial << " " << result.status;
    const double crank = (edited.joints[2].position - edited.joints[0].position).norm();
    EXPECT_GT(crank, 1.2) << trial;
    EXPECT_LT(crank, 10) << trial;
    EXPECT_LT(result.energy_after, result.energy_before);
  }
}

TEST(LinkageEdit, EnvelopePullsTheMotionInside) {
  const Linkage linkage = test::example("four_bar_crank_rocker.json");
  const auto angles = edit_sample_angles(linkage, 72);
  double y_max = -1e9;
  for (int j = 0; j < static_cast<int>(linkage.joints.size()); ++j)
    for (const auto& p : joint_trajectory(linkage, j, angles)) y_max = std::max(y_max, p.y());
  EditObjectives objectives;
  objectives.envelope = EditObjectives::Envelope{Eigen::Vector2d(-100, -100), Eigen::Vector2d(100, y_max - 0.5), 10};
  objectives.regularization_weight = 0.01;
  const EditResult result = edit_linkage(linkage, objectives);
  double y_max_after = -1e9;
  for (int j = 0; j < static_cast<int>(linkage.joints.size()); ++j)
    for (const auto& p : joint_trajectory(result.linkage, j, angles)) y_max_after = std::max(y_max_after, p.y());
  EXPECT_LT(y_max_after, y_max - 0.3) << result.status;
}

TEST(LinkageEdit, SessionUpdatesTheReferencesAfterEachEdit) {
  EditSession session(test::example("four_bar_crank_rocker.json"));
  const int C = session.linkage().find_joint("C");
  EditObjectives first;
  first.drags.push_back({C, session.linkage().joints[C].position + Eigen::Vector2d(0.3, -0.2), std::nullopt, 1});
  const EditResult result = session.edit(first);
  EXPECT_LT(result.energy_after, result.energy_before);
  EXPECT_EQ(session.reference_lengths(), link_lengths(session.linkage()));
  // With nothing asked, the next edit keeps the linkage: the regularizer is already at rest.
  const Eigen::Matrix2Xd before = session.linkage().initial_positions();
  session.edit(EditObjectives{});
  EXPECT_LT((session.linkage().initial_positions() - before).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace reconfig::linkage
