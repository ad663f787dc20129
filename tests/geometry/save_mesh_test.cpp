#include "reconfig/geometry/save_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <limits>
#include <random>

#include "mesh_test_helpers.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/primitives.h"
#include "support/test_data.h"

namespace reconfig::geometry {
namespace {

namespace fs = std::filesystem;
using reconfig::testing::fresh_temp_dir;
using testing::canonical;
using testing::read_bytes;
using testing::rounded_to_float;
using testing::same_mesh;

/// A sphere, turned and moved to arbitrary (not float-representable) coordinates.
Mesh rotated_sphere(unsigned seed) {
  Mesh mesh = make_sphere(0.37, 2);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-100, 100);
  Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
  q.normalize();
  const Eigen::Vector3d t(u(rng), u(rng), u(rng));
  for (int v = 0; v < mesh.vertex_count(); ++v) mesh.V.row(v) = (q * Eigen::Vector3d(mesh.V.row(v)) + t).transpose();
  return mesh;
}

TEST(SaveMesh, ObjRoundTripsExactly) {
  const fs::path path = fresh_temp_dir() / "sphere.obj";
  const Mesh mesh = rotated_sphere(1);  // arbitrary doubles
  save_obj(path, mesh);
  const Mesh back = load_mesh(path);
  EXPECT_EQ(back.V, mesh.V);  // same numbers, same order
  EXPECT_EQ(back.F, mesh.F);
}

TEST(SaveMesh, ObjWritesSeventeenDigits) {
  const fs::path path = fresh_temp_dir() / "tri.obj";
  Mesh tri;
  tri.V.resize(3, 3);
  tri.V << 0.1, 1.0 / 3, -2e-300, 1, 0, 0, 0, 1, 0;
  tri.F.resize(1, 3);
  tri.F << 0, 1, 2;
  save_obj(path, tri);
  const std::string text = read_bytes(path.string());
  EXPECT_NE(text.find("v 0.10000000000000001 0.33333333333333331 -2.0000000000000001e-300\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("f 1 2 3\n"), std::string::npos);
}

TEST(SaveMesh, StlRoundTripsUpToVertexOrderAndFloatRounding) {
  const fs::path dir = fresh_temp_dir();
  for (unsigned seed = 0; seed < 5; ++seed) {
    const Mesh mesh = rotated_sphere(seed);
    for (bool binary : {true, false}) {
      SCOPED_TRACE(binary ? "binary" : "ascii");
      const fs::path path = dir / (binary ? "b.stl" : "a.stl");
      save_stl(path, mesh, binary);
      const Mesh back = load_mesh(path);
      EXPECT_TRUE(same_mesh(back, rounded_to_float(mesh)));
    }
  }
  // Binary layout: 80-byte header, count, 50 bytes per triangle.
  save_stl(dir / "b.stl", make_box({1, 1, 1}), true);
  EXPECT_EQ(fs::file_size(dir / "b.stl"), 84u + 12u * 50u);
  EXPECT_EQ(read_bytes((dir / "a.stl").string()).rfind("solid reconfig\n", 0), 0u);
}

TEST(SaveMesh, WritesAtomicallyAndReplacesTheOldFile) {
  const fs::path dir = fresh_temp_dir();
  save_obj(dir / "part.obj", make_box({1, 1, 1}));
  save_obj(dir / "part.obj", make_box({2, 2, 2}));
  EXPECT_FALSE(fs::exists(dir / "part.obj.tmp"));
  EXPECT_DOUBLE_EQ(load_mesh(dir / "part.obj").V.maxCoeff(), 1.0);
  save_stl(dir / "part.stl", make_box({1, 1, 1}));
  EXPECT_FALSE(fs::exists(dir / "part.stl.tmp"));
}

TEST(SaveMesh, UnwritablePathIsAnInputErrorAndLeavesNothingBehind) {
  const fs::path dir = fresh_temp_dir();
  EXPECT_THROW(save_obj(dir / "no" / "such" / "folder.obj", make_box({1, 1, 1})), InputError);
  // Renaming onto a folder fails: the old folder stays, the temporary file is removed.
  fs::create_directories(dir / "taken.stl" / "inside");
  EXPECT_THROW(save_stl(dir / "taken.stl", make_box({1, 1, 1})), InputError);
  EXPECT_FALSE(fs::exists(dir / "taken.stl.tmp"));
  EXPECT_TRUE(fs::is_directory(dir / "taken.stl"));
}

TEST(SaveMesh, RefusesNonFiniteCoordinates) {
  Mesh box = make_box({1, 1, 1});
  box.V(6, 2) = std::numeric_limits<double>::quiet_NaN();
  const fs::path path = fresh_temp_dir() / "bad.stl";
  try {
    save_stl(path, box);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.location(), "vertex 6");
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(SaveMesh, RefusesOutOfRangeIndices) {
  Mesh box = make_box({1, 1, 1});
  box.F(3, 2) = 99;
  const fs::path path = fresh_temp_dir() / "bad.obj";
  try {
    save_obj(path, box);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.location(), "face 3");
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(SaveMesh, ObjObjectsAreNamedAndReadBackAsOneMesh) {
  const fs::path path = fresh_temp_dir() / "parts.obj";
  Mesh box = make_box({1, 1, 1});
  box.V.col(0).array() += 5;  // apart from the sphere, so welding on loading merges nothing
  const Mesh sphere = rotated_sphere(2);
  save_obj(path, std::vector<ObjObject>{{"box", box}, {"a sphere\twith\nspaces", sphere}});
  const std::string text = read_bytes(path.string());
  EXPECT_NE(text.find("\no box\nv "), std::string::npos) << text.substr(0, 200);
  EXPECT_NE(text.find("\no a_sphere_with_spaces\nv "), std::string::npos);
  // The sphere's faces are numbered after the box's 8 vertices.
  const std::size_t sphere_start = text.find("o a_sphere");
  EXPECT_NE(text.find("\nf " + std::to_string(sphere.F(0, 0) + 9) + " ", sphere_start), std::string::npos);
  const Mesh back = load_mesh(path);
  EXPECT_EQ(back.face_count(), box.face_count() + sphere.face_count());
  EXPECT_EQ(back.vertex_count(), box.vertex_count() + sphere.vertex_count());
  EXPECT_EQ(Eigen::MatrixX3d(back.V.bottomRows(sphere.vertex_count())), sphere.V);
}

}  // namespace
}  // namespace reconfig::geometry
