#include "reconfig/sweep/carve_part.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "reconfig/collision/reference_check.h"
#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/signed_distance.h"
#include "reconfig/scene/validate_scene.h"
#include "reconfig/sweep/subtract_meshes.h"

namespace reconfig::sweep {
namespace {

scene::Part box_part(const std::string& name, const Eigen::Vector3d& size) {
  scene::Part part;
  part.name = name;
  part.source = scene::BoxPrimitive{size};
  part.mesh = scene::Part::primitive_mesh(part.source);
  return part;
}

/// A 0.4 m block at the origin and a rod of square section `width` pushed along z straight
/// through it, from z = −0.6 to z = 0.6.
scene::Reconfigurable rod_through_block(double width) {
  scene::Reconfigurable scene;
  scene.parts = {box_part("block", {0.4, 0.4, 0.4}), box_part("rod", {width, width, 0.3})};
  const motion::Pose below{Eigen::Quaterniond::Identity(), {0, 0, -0.6}};
  const motion::Pose above{Eigen::Quaterniond::Identity(), {0, 0, 0.6}};
  scene.states = {{"down", {{"rod", below}}}, {"up", {{"rod", above}}}};
  scene::KeyframedTrack track;
  const Eigen::Vector3d a = below.translation, b = above.translation;
  track.translation = {{0.0, a, a, a + (b - a) / 3}, {1.0, b, b - (b - a) / 3, b}};
  scene.transitions = {{"push", "down", "up", true, {{"rod", track}}}};
  return scene;
}

/// Where the carved block's material starts again along the ray from (0, 0, z) in direction
/// `direction` (in the xy plane), by bisection between the axis (empty) and `far` (solid).
double channel_wall(const geometry::MeshSignedDistance& carved, const Eigen::Vector3d& direction, double z, double far) {
  double empty = 0, solid = far;
  for (int i = 0; i < 24; ++i) {
    const double mid = 0.5 * (empty + solid);
    (carved.query(Eigen::Vector3d(0, 0, z) + mid * direction).distance < 0 ? solid : empty) = mid;
  }
  return solid;
}

TEST(CarvePart, RodPushedThroughABlockLeavesAChannelOfRodPlusTwoOffsets) {
  const double width = 0.1, epsilon = 0.015, h = 0.008;
  const scene::Reconfigurable scene = rod_through_block(width);
  collision::ReferenceCheckRequest reference;
  reference.samples = 150;
  ASSERT_TRUE(collision::reference_check(scene, reference).any_collision());  // it does collide first
  CarveRequest request;
  request.part = 0;
  request.carvers = {1};
  request.sweep.grid_step = h;
  request.sweep.offset = epsilon;
  const CarveResult result = carve_part(scene, request);
  ASSERT_TRUE(result.ok()) << result.problem;
  EXPECT_TRUE(result.sweeps[0].verified);  // the tight level passed its clearance check
  std::printf("sweep: %d samples, motion error %.3f h, level e + %.3f h\n", result.sweeps[0].time_samples,
              result.sweeps[0].motion_error / h, result.sweeps[0].margin / h);
  EXPECT_TRUE(geometry::check_mesh(result.mesh).is_valid_solid()) << geometry::check_mesh(result.mesh).summary();
  // Across the channel, along x and along y, at three heights: the width is rod + 2ε within h
  // (conservative: never narrower than rod + 2ε).
  const geometry::MeshSignedDistance carved_distance(result.mesh);
  for (double z : {-0.15, 0.0, 0.12}) {
    for (const Eigen::Vector3d& axis : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)}) {
      const double across = channel_wall(carved_distance, axis, z, 0.19) + channel_wall(carved_distance, -axis, z, 0.19);
      std::printf("channel width at z %.2f along %s: %.5f = rod + 2e + %.3f h\n", z, axis.x() ? "x" : "y", across,
                  (across - width - 2 * epsilon) / h);
      EXPECT_GE(across, width + 2 * epsilon) << "z " << z;
      EXPECT_LE(across, width + 2 * epsilon + h) << "z " << z;
    }
  }
  // The channel is a channel: the carved volume is about its section times the block's height.
  const double channel = (width + 2 * epsilon) * (width + 2 * epsilon) * 0.4;
  EXPECT_GE(result.volume_before - result.volume_after, channel);
  EXPECT_LE(result.volume_before - result.volume_after, (width + 2 * epsilon + h) * (width + 2 * epsilon + h) * 0.4);
  // And the carved design no longer collides (the dense-sampling oracle).
  scene::Reconfigurable carved = scene;
  carved.parts[0].mesh = result.mesh;
  EXPECT_FALSE(collision::reference_check(carved, reference).any_collision());
}

TEST(CarvePart, KeepsEveryTriangleAwayFromTheCut) {
  const scene::Reconfigurable scene = rod_through_block(0.1);
  CarveRequest request;
  request.part = 0;
  request.carvers = {1};
  request.sweep.grid_step = 0.01;
  const CarveResult result = carve_part(scene, request);
  ASSERT_TRUE(result.ok()) << result.problem;
  // The block's corners are untouched, bit for bit.
  const geometry::Mesh& block = scene.parts[0].mesh;
  for (int v = 0; v < block.vertex_count(); ++v) {
    bool found = false;
    for (int w = 0; w < result.mesh.vertex_count() && !found; ++w) found = result.mesh.V.row(w) == block.V.row(v);
    EXPECT_TRUE(found) << v;
  }
}

TEST(CarvePart, ACarverThatNeverReachesThePartLeavesItAsItIs) {
  scene::Reconfigurable scene = rod_through_block(0.1);
  scene.parts.push_back(box_part("far", {0.1, 0.1, 0.1}));
  scene.states[0].poses["far"] = {Eigen::Quaterniond::Identity(), {5, 0, 0}};
  scene.states[1].poses["far"] = {Eigen::Quaterniond::Identity(), {5, 0, 0}};
  CarveRequest request;
  request.part = 0;
  request.carvers = {2};
  const CarveResult result = carve_part(scene, request);
  ASSERT_TRUE(result.ok()) << result.problem;
  EXPECT_TRUE(result.sweeps[0].mesh.empty());
  EXPECT_TRUE(result.mesh.V == scene.parts[0].mesh.V && result.mesh.F == scene.parts[0].mesh.F);
}

TEST(SubtractMeshes, RefusesAnOpenCutterAndChangesNothing) {
  const geometry::Mesh solid = scene::Part::primitive_mesh(scene::BoxPrimitive{{1, 1, 1}});
  geometry::Mesh open = scene::Part::primitive_mesh(scene::BoxPrimitive{{0.5, 0.5, 2}});
  open.F.conservativeResize(open.F.rows() - 1, 3);
  const SubtractionResult result = subtract_meshes(solid, {open});
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.problem.find("cutter 1: open"), std::string::npos) << result.problem;
  EXPECT_TRUE(result.mesh.V == solid.V && result.mesh.F == solid.F);
}

TEST(SubtractMeshes, SeveralCuttersAtOnce) {
  const geometry::Mesh solid = scene::Part::primitive_mesh(scene::BoxPrimitive{{1, 1, 1}});
  geometry::Mesh a = scene::Part::primitive_mesh(scene::BoxPrimitive{{0.2, 0.2, 2}});
  geometry::Mesh b = a;
  b.V.col(0).array() += 0.3;
  const SubtractionResult result = subtract_meshes(solid, {a, b});
  ASSERT_TRUE(result.ok()) << result.problem;
  EXPECT_NEAR(geometry::mass_properties(result.mesh).volume, 1 - 2 * 0.04, 1e-12);
  EXPECT_TRUE(geometry::check_mesh(result.mesh).is_valid_solid());
}

}  // namespace
}  // namespace reconfig::sweep
