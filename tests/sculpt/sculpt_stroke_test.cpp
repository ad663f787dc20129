#include "reconfig/sculpt/sculpt_stroke.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "reconfig/geometry/primitives.h"
#include "reconfig/geometry/self_intersections.h"
#include "reconfig/sculpt/vertex_normals.h"

namespace reconfig::sculpt {
namespace {

Eigen::MatrixX3d no_normals() { return Eigen::MatrixX3d(0, 3); }

/// A random tool of each shape near `center`, about `size` across.
Tool random_tool(std::mt19937& random, const Eigen::Vector3d& center, double size) {
  std::uniform_real_distribution<double> unit(0.5, 1.0);
  const double coating = size * unit(random);
  switch (random() % 4) {
    case 0: return Tool::sphere(size * unit(random), center, coating);
    case 1: return Tool::box(size * Eigen::Vector3d(unit(random), unit(random), unit(random)), center, coating);
    case 2: return Tool::capsule(size * unit(random) / 2, size * unit(random), center, coating);
    default: return Tool::ellipsoid(size * Eigen::Vector3d(unit(random), unit(random), unit(random)), center, coating);
  }
}

/// Random translations (up to 10× the tool's size), scalings and rotations (up to full turns).
ToolMotion random_motion(std::mt19937& random, const Eigen::Vector3d& center, double size) {
  std::uniform_real_distribution<double> unit(-1, 1);
  const Eigen::Vector3d direction(unit(random), unit(random), unit(random));
  switch (random() % 3) {
    case 0: return ToolMotion::translation(10 * size * unit(random) * direction.normalized());
    case 1: return ToolMotion::scaling(std::exp(1.2 * unit(random)), center);
    default: {
      const Eigen::Vector3d pivot = center + size * Eigen::Vector3d(unit(random), unit(random), unit(random));
      return ToolMotion::rotation(direction, 2 * M_PI * unit(random), pivot);
    }
  }
}

/// Translations up to the tool's size, scalings by up to e^±0.4, rotations up to 0.6 rad.
ToolMotion gentle_motion(std::mt19937& random, const Eigen::Vector3d& center, double size) {
  std::uniform_real_distribution<double> unit(-1, 1);
  const Eigen::Vector3d direction = Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
  switch (random() % 3) {
    case 0: return ToolMotion::translation(size * unit(random) * direction);
    case 1: return ToolMotion::scaling(std::exp(0.4 * unit(random)), center);
    default: return ToolMotion::rotation(direction, 0.6 * unit(random), center + size * direction.unitOrthogonal());
  }
}

TEST(SculptStroke, PointsBeyondTheCoatingAreBitForBitUnchanged) {
  geometry::Mesh mesh = geometry::make_sphere(1.0, 4);
  const geometry::Mesh before = mesh;
  const Eigen::Vector3d start(1, 0, 0), d(0.5, 0.3, -0.2);
  const double radius = 0.3, coating = 0.25;
  Eigen::MatrixX3d N = vertex_normals(mesh);
  const Eigen::MatrixX3d normals_before = N;
  const StrokeResult result =
      sculpt_mesh({{Tool::sphere(radius, start, coating), ToolMotion::translation(d)}}, {}, mesh, N);
  ASSERT_TRUE(result.applied) << result.refusal;
  int far = 0, moved = 0;
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const Eigen::Vector3d p = before.V.row(i);
    const double t = std::clamp((p - start).dot(d) / d.squaredNorm(), 0.0, 1.0);
    if ((p - start - t * d).norm() >= radius + coating) {  // beyond the coating all along the swept capsule
      ++far;
      EXPECT_TRUE(mesh.V.row(i) == before.V.row(i)) << i;
      EXPECT_TRUE(N.row(i) == normals_before.row(i)) << i;
    }
    moved += mesh.V.row(i) != before.V.row(i);
  }
  EXPECT_GT(far, 1000);
  EXPECT_GT(moved, 50);
  EXPECT_EQ(moved, result.vertices_moved);
}

TEST(SculptStroke, PointsInsideTheToolFollowItExactly) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 24; ++trial) {
    const Eigen::Vector3d center(unit(random), unit(random), unit(random));
    const Tool tool = random_tool(random, center, 0.3);
    const ToolMotion motion = random_motion(random, center, 0.3);
    std::vector<Eigen::Vector3d> inside;
    while (inside.size() < 50) {
      const Eigen::Vector3d p = center + 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random));
      if (tool.distance(p) < 0) inside.push_back(p);
    }
    Eigen::MatrixX3d V(inside.size(), 3), N = no_normals();
    for (std::size_t i = 0; i < inside.size(); ++i) V.row(i) = inside[i].transpose();
    const StrokeResult result = deform_points({{tool, motion}}, {}, V, N);
    ASSERT_TRUE(result.applied) << result.refusal;
    for (std::size_t i = 0; i < inside.size(); ++i)
      EXPECT_LT((V.row(i).transpose() - motion.apply(inside[i], 1.0)).norm(), 1e-9) << trial;
  }
}

TEST(SculptStroke, SubstepCountsAreTheClosedFormBoundsOfSection4) {
  const Tool tool = Tool::sphere(0.2, {0.5, 0, 0}, 0.1);
  const Eigen::Vector3d d(1.0, 0.5, 0.25);
  EXPECT_DOUBLE_EQ(foldover_bound({{tool, ToolMotion::translation(d)}}), 1.875 * d.norm() / 0.1);
  EXPECT_EQ(substep_count({{tool, ToolMotion::translation(d)}}), static_cast<int>(std::floor(1.875 * d.norm() / 0.1)) + 1);
  // Scaling by σ about the tool's center: S_max is the half diagonal of the field box, grown by σ at the end.
  const double sigma = 2.5;
  const double s_max = std::sqrt(3.0) * (0.2 * sigma + 0.1);
  EXPECT_NEAR(foldover_bound({{tool, ToolMotion::scaling(sigma, {0.5, 0, 0})}}), 1.875 * std::log(sigma) * s_max / 0.1, 1e-12);
  // Rotation by θ about the z axis through the origin: R_max is the farthest box corner from the axis.
  const double theta = 1.2, r_max = std::hypot(0.5 + 0.3, 0.3);
  EXPECT_NEAR(foldover_bound({{tool, ToolMotion::rotation({0, 0, 1}, theta, {0, 0, 0})}}), 1.875 * theta * r_max / 0.1,
              0.2 * 1.875 * theta / 0.1);  // the end box is the rotated one's box: R_max grows a little
  EXPECT_GE(foldover_bound({{tool, ToolMotion::rotation({0, 0, 1}, theta, {0, 0, 0})}}), 1.875 * theta * r_max / 0.1);
}

TEST(SculptStroke, RandomStrokesKeepTheJacobianDeterminantPositive) {
  // Translations up to 10× the tool's size in one stroke, rotations up to full turns: det J is
  // measured on the grid and at every vertex of every sub-step.
  std::mt19937 random(11);
  geometry::Mesh mesh = geometry::make_sphere(1.0, 3);
  Eigen::MatrixX3d N = vertex_normals(mesh);
  int moved = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const Eigen::Vector3d center = mesh.V.row(random() % mesh.vertex_count());
    const StrokeResult result =
        deform_points({{random_tool(random, center, 0.25), random_motion(random, center, 0.25)}}, {}, mesh.V, N);
    ASSERT_TRUE(result.applied) << trial << ": " << result.refusal;
    EXPECT_GT(result.min_jacobian_determinant, 0);
    EXPECT_LT(result.min_jacobian_determinant, 1);  // the coating was reached and compressed
    moved += result.vertices_moved;
  }
  EXPECT_GT(moved, 200);
}

TEST(SculptStroke, RandomModerateStrokesKeepTheMeshFreeOfSelfIntersections) {
  std::mt19937 random(23);
  geometry::Mesh mesh = geometry::make_sphere(1.0, 4);
  Eigen::MatrixX3d N = vertex_normals(mesh);
  int moved = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Eigen::Vector3d center = mesh.V.row(random() % mesh.vertex_count());
    const StrokeResult result =
        sculpt_mesh({{random_tool(random, center, 0.25), gentle_motion(random, center, 0.25)}}, {}, mesh, N);
    ASSERT_TRUE(result.applied) << trial << ": " << result.refusal;
    moved += result.vertices_moved;
  }
  EXPECT_GT(moved, 500);
  EXPECT_TRUE(geometry::find_self_intersections(mesh, 1).pairs.empty());
}

TEST(SculptStroke, LongPullsAndFullTwistsWithRemeshingKeepTheMeshFreeOfSelfIntersections) {
  // Translations up to 10× the tool's size, scalings, and full turns of the tool about its own
  // center, the mesh remeshed between sub-steps (§5.1). (Full turns about a pivot outside the
  // tool can wind the coating tighter than the mesh resolves: such strokes are refused.)
  std::mt19937 random(29);
  std::uniform_real_distribution<double> unit(-1, 1);
  StrokeOptions options;
  options.remesh = {0.1, 0.02};
  int splits = 0;
  for (int trial = 0; trial < 9; ++trial) {
    geometry::Mesh mesh = geometry::make_sphere(1.0, 3);
    Eigen::MatrixX3d N = vertex_normals(mesh);
    const Eigen::Vector3d center = mesh.V.row(random() % mesh.vertex_count());
    const Eigen::Vector3d direction = Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
    const ToolMotion motions[3] = {ToolMotion::translation(2.5 * unit(random) * direction),
                                   ToolMotion::scaling(std::exp(1.2 * unit(random)), center),
                                   ToolMotion::rotation(direction, 2 * M_PI * unit(random), center)};
    const StrokeResult result = sculpt_mesh({{random_tool(random, center, 0.25), motions[trial % 3]}}, options, mesh, N);
    ASSERT_TRUE(result.applied) << trial << ": " << result.refusal;
    EXPECT_GT(result.min_jacobian_determinant, 0);
    EXPECT_TRUE(geometry::find_self_intersections(mesh, 1).pairs.empty());
    splits += result.splits;
  }
  EXPECT_GT(splits, 100);
}

TEST(SculptStroke, AStrokeAndItsInverseReturnEveryVertex) {
  std::mt19937 random(13);
  for (int trial = 0; trial < 16; ++trial) {
    geometry::Mesh mesh = geometry::make_sphere(1.0, 3);
    const Eigen::MatrixX3d rest = mesh.V;
    const Eigen::Vector3d center = mesh.V.row(random() % mesh.vertex_count());
    const ToolMotion motion = random_motion(random, center, 0.25);
    Eigen::MatrixX3d N = no_normals();
    StrokeOptions options;
    options.check_self_intersections = false;
    const StrokeResult forward = sculpt_mesh({{random_tool(random, center, 0.25), motion}}, options, mesh, N);
    ASSERT_TRUE(forward.applied) << forward.refusal;
    const StrokeResult back = sculpt_mesh({{forward.tools[0], motion.inverse()}}, options, mesh, N);
    ASSERT_TRUE(back.applied) << back.refusal;
    EXPECT_EQ(back.substeps, forward.substeps);
    EXPECT_LT((mesh.V - rest).rowwise().norm().maxCoeff(), 1e-6) << trial;
    EXPECT_GT(forward.vertices_moved, 0);
  }
}

TEST(SculptStroke, ClosedFormsAgreeWithTheLogSpaceBlend) {
  std::mt19937 random(17);
  for (int trial = 0; trial < 12; ++trial) {
    const geometry::Mesh mesh = geometry::make_sphere(1.0, 2);
    const Eigen::Vector3d center = mesh.V.row(random() % mesh.vertex_count());
    const MovingTool moving{random_tool(random, center, 0.3), random_motion(random, center, 0.3)};
    Eigen::MatrixX3d closed_V = mesh.V, closed_N = vertex_normals(mesh), blended_V = closed_V, blended_N = closed_N;
    StrokeOptions options;
    options.grid = 0;
    const StrokeResult closed = deform_points({moving}, options, closed_V, closed_N);
    options.blended = true;
    const StrokeResult blended = deform_points({moving}, options, blended_V, blended_N);
    ASSERT_TRUE(closed.applied && blended.applied);
    EXPECT_LT((closed_V - blended_V).rowwise().norm().maxCoeff(), 1e-9) << trial;
    EXPECT_LT((closed_N - blended_N).rowwise().norm().maxCoeff(), 1e-5) << trial;
    EXPECT_NEAR(closed.min_jacobian_determinant, blended.min_jacobian_determinant, 1e-6);
  }
}

/// Normals by finite differences: two tangents at each point, their images crossed.
TEST(SculptStroke, NormalsAgreeWithFiniteDifferencesAndTheDeformedFaces) {
  std::mt19937 random(19);
  const double e = 1e-5;
  for (int trial = 0; trial < 9; ++trial) {
    geometry::Mesh mesh = geometry::make_sphere(1.0, 5);
    const Eigen::Vector3d center = mesh.V.row(random() % mesh.vertex_count());
    const MovingTool moving{random_tool(random, center, 0.4), gentle_motion(random, center, 0.2)};
    const Eigen::MatrixX3d N0 = vertex_normals(mesh);
    const int n = 200;
    Eigen::MatrixX3d V(5 * n, 3), N = Eigen::MatrixX3d::Zero(5 * n, 3);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d p = center + 0.5 * Eigen::Vector3d::Random(), normal = Eigen::Vector3d::Random().normalized();
      const Eigen::Vector3d t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);
      V.row(5 * i) = p.transpose();
      N.row(5 * i) = normal.transpose();
      V.row(5 * i + 1) = (p + e * t1).transpose(), V.row(5 * i + 2) = (p - e * t1).transpose();
      V.row(5 * i + 3) = (p + e * t2).transpose(), V.row(5 * i + 4) = (p - e * t2).transpose();
    }
    const StrokeResult result = deform_points({moving}, {}, V, N);
    ASSERT_TRUE(result.applied) << result.refusal;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d a = V.row(5 * i + 1) - V.row(5 * i + 2), b = V.row(5 * i + 3) - V.row(5 * i + 4);
      EXPECT_LT((a.cross(b).normalized() - N.row(5 * i).transpose()).norm(), 1e-5) << trial << " " << i;
    }
    Eigen::MatrixX3d mesh_normals = N0;  // the mesh itself: its deformed normals against its deformed faces
    ASSERT_TRUE(sculpt_mesh({moving}, {}, mesh, mesh_normals).applied);
    const Eigen::MatrixX3d faces = vertex_normals(mesh);
    EXPECT_LT((faces - mesh_normals).rowwise().norm().maxCoeff(), 0.05) << trial;
  }
}

TEST(SculptStroke, TooFewSubstepsFoldSpaceAndTheStrokeIsRefused) {
  geometry::Mesh mesh = geometry::make_sphere(1.0, 3);
  const geometry::Mesh before = mesh;
  Eigen::MatrixX3d N = no_normals();
  const MovingTool pull{Tool::sphere(0.2, {1, 0, 0}, 0.1), ToolMotion::translation({2, 0, 0})};
  ASSERT_GT(foldover_bound({pull}), 30);  // one step is far below the bound
  StrokeOptions options;
  options.substeps = 1;
  const StrokeResult result = sculpt_mesh({pull}, options, mesh, N);
  EXPECT_FALSE(result.applied);
  EXPECT_NE(result.refusal.find("folds space over"), std::string::npos) << result.refusal;
  EXPECT_TRUE(mesh.V == before.V);
  options.substeps = 0;  // with the bound's count the same stroke is fine
  EXPECT_TRUE(sculpt_mesh({pull}, options, mesh, N).applied);
}

TEST(SculptStroke, AStrokeThatMakesTheMeshSelfIntersectIsRefused) {
  // A slab and a small cube above it; the tool pushes the cube into the slab's top face, whose
  // flat triangles span vertices far beyond the coating (space bends, the coarse faces cannot).
  geometry::Mesh mesh = geometry::make_box({2, 2, 0.2});
  const geometry::Mesh cube = geometry::make_box({0.1, 0.1, 0.1});
  const int n = mesh.vertex_count();
  mesh.V.conservativeResize(n + cube.vertex_count(), 3);
  mesh.V.bottomRows(cube.vertex_count()) = cube.V.rowwise() + Eigen::RowVector3d(0, 0, 0.3);
  mesh.F.conservativeResize(mesh.face_count() + cube.face_count(), 3);
  mesh.F.bottomRows(cube.face_count()) = cube.F.array() + n;
  ASSERT_TRUE(geometry::find_self_intersections(mesh, 1).pairs.empty());
  const geometry::Mesh before = mesh;
  Eigen::MatrixX3d N = no_normals();
  const MovingTool push{Tool::sphere(0.15, {0, 0, 0.3}, 0.3), ToolMotion::translation({0, 0, -0.2})};
  const StrokeResult result = sculpt_mesh({push}, {}, mesh, N);
  EXPECT_FALSE(result.applied);
  EXPECT_GT(result.min_jacobian_determinant, 0);  // space did not fold: the mesh did
  EXPECT_NE(result.refusal.find("self-intersect"), std::string::npos) << result.refusal;
  EXPECT_TRUE(mesh.V == before.V);
}

/// A slab and, above it, a small finely meshed ball (edges of about 0.016).
geometry::Mesh slab_and_ball() {
  geometry::Mesh mesh = geometry::make_box({2, 2, 0.2});
  const geometry::Mesh ball = geometry::make_sphere(0.06, 2);
  const int n = mesh.vertex_count();
  mesh.V.conservativeResize(n + ball.vertex_count(), 3);
  mesh.V.bottomRows(ball.vertex_count()) = ball.V.rowwise() + Eigen::RowVector3d(0, 0, 0.3);
  mesh.F.conservativeResize(mesh.face_count() + ball.face_count(), 3);
  mesh.F.bottomRows(ball.face_count()) = ball.F.array() + n;
  return mesh;
}

TEST(SculptStroke, ARefusedStrokeLeavesTheMeshBitForBitAsItWas) {
  // The ball pushed into the slab in two sub-steps, remeshed after each (splits; collapses
  // renumber the mesh): the self-intersection refuses the stroke at its end and the undo log
  // puts everything back.
  const MovingTool push{Tool::sphere(0.15, {0, 0, 0.3}, 0.3), ToolMotion::translation({0, 0, -0.2})};
  for (const RemeshOptions remesh : {RemeshOptions{}, RemeshOptions{0.012, 0}, RemeshOptions{0.05, 0.02}}) {
    geometry::Mesh mesh = slab_and_ball();
    ASSERT_TRUE(geometry::find_self_intersections(mesh, 1).pairs.empty());
    Eigen::MatrixX3d N = vertex_normals(mesh);
    const geometry::Mesh before = mesh;
    const Eigen::MatrixX3d normals_before = N;
    StrokeOptions options;
    options.remesh = remesh;
    MeshIndex index(mesh);
    const StrokeResult result = sculpt_mesh({push}, options, mesh, N, index);
    ASSERT_FALSE(result.applied);
    EXPECT_NE(result.refusal.find("self-intersect"), std::string::npos) << result.refusal;
    EXPECT_EQ(result.substeps, 2);
    if (remesh.max_edge == 0.012) {
      EXPECT_GT(result.splits, 0);
    }
    if (remesh.min_edge > 0) {
      EXPECT_GT(result.collapses, 0);
    }
    EXPECT_TRUE(mesh.V == before.V);
    EXPECT_TRUE(mesh.F == before.F);
    EXPECT_TRUE(N == normals_before);
    EXPECT_EQ(index.vertex_count(), mesh.vertex_count());
    EXPECT_EQ(index.face_count(), mesh.face_count());
  }
}

TEST(SculptStroke, AMirroredStrokeIsSymmetric) {
  geometry::Mesh mesh = geometry::make_sphere(1.0, 3);  // symmetric in x = 0
  std::vector<int> mirror(mesh.vertex_count(), -1);
  for (int i = 0; i < mesh.vertex_count(); ++i)
    for (int j = 0; j < mesh.vertex_count(); ++j)
      if ((mesh.V.row(j) - Eigen::RowVector3d(-mesh.V(i, 0), mesh.V(i, 1), mesh.V(i, 2))).norm() < 1e-12) mirror[i] = j;
  ASSERT_EQ(std::count(mirror.begin(), mirror.end(), -1), 0);
  const geometry::Mesh before = mesh;
  Eigen::MatrixX3d N = vertex_normals(mesh);
  StrokeOptions options;
  options.mirror = {0, 0.0};
  const MovingTool pull{Tool::sphere(0.25, {0.8, 0.3, 0.5}, 0.3), ToolMotion::translation({0.4, 0.1, 0.3})};
  const StrokeResult result = sculpt_mesh({pull}, options, mesh, N);
  ASSERT_TRUE(result.applied) << result.refusal;
  int left = 0, right = 0;
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    EXPECT_NEAR(mesh.V(mirror[i], 0), -mesh.V(i, 0), 1e-9);
    EXPECT_NEAR(mesh.V(mirror[i], 1), mesh.V(i, 1), 1e-9);
    EXPECT_NEAR(mesh.V(mirror[i], 2), mesh.V(i, 2), 1e-9);
    if (mesh.V.row(i) != before.V.row(i)) (before.V(i, 0) < 0 ? left : right) += 1;
  }
  EXPECT_GT(left, 10);
  EXPECT_EQ(left, right);
}

TEST(SculptStroke, BlendedToolsAreNormalized) {
  // Two identical tools translating by d: the inside moves by d, not 2d (eq. 2's normalization).
  const Tool tool = Tool::sphere(0.3, {0, 0, 0}, 0.2);
  const ToolMotion move = ToolMotion::translation({0.5, 0, 0});
  Eigen::MatrixX3d V(2, 3), N = no_normals();
  V << 0.1, 0.1, 0, -0.1, 0, 0.1;
  const Eigen::MatrixX3d before = V;
  const StrokeResult result = deform_points({{tool, move}, {tool, move}}, {}, V, N);
  ASSERT_TRUE(result.applied);
  EXPECT_EQ(result.substeps, substep_count({{tool, move}, {tool, move}}));
  EXPECT_LT((V - (before.rowwise() + Eigen::RowVector3d(0.5, 0, 0))).norm(), 1e-9);
}

}  // namespace
}  // namespace reconfig::sculpt
