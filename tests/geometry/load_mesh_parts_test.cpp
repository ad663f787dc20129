#include <gtest/gtest.h>

#include "reconfig/common/input_error.h"
#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/mesh_check.h"
#include "support/test_data.h"

namespace reconfig::geometry {
namespace {

TEST(LoadMeshParts, AGltfWithTwoMeshesGivesTwoPlacedMeshes) {
  const auto meshes = load_mesh_parts(testing::source_dir() / "tests/data/two_tetrahedra.gltf");
  ASSERT_EQ(meshes.size(), 2u);
  EXPECT_EQ(meshes[0].name, "small_tet");
  EXPECT_EQ(meshes[1].name, "big_tet");
  for (const NamedMesh& part : meshes) EXPECT_TRUE(check_mesh(part.mesh).is_valid_solid());
  const MassProperties small = mass_properties(meshes[0].mesh), big = mass_properties(meshes[1].mesh);
  EXPECT_NEAR(small.volume, 1.0 / 6, 1e-6);
  EXPECT_NEAR(big.volume, 8.0 / 6, 1e-6);  // scaled by 2: placed by its node
  EXPECT_NEAR(small.bounds.min().x(), -2, 1e-6);
  EXPECT_NEAR(big.bounds.max().x(), 4, 1e-6);
  // Together they are what load_mesh reads.
  EXPECT_EQ(load_mesh(testing::source_dir() / "tests/data/two_tetrahedra.gltf").face_count(), 8);
}

TEST(LoadMeshParts, AnObjIsOneMesh) {
  const auto meshes = load_mesh_parts(testing::source_dir() / "examples/bench-table/meshes/seat.obj");
  ASSERT_EQ(meshes.size(), 1u);
  EXPECT_EQ(meshes[0].mesh.F, load_mesh(testing::source_dir() / "examples/bench-table/meshes/seat.obj").F);
}

TEST(LoadMeshParts, AMissingFileIsNamed) {
  try {
    load_mesh_parts("/no/such/mesh.glb");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "/no/such/mesh.glb");
  }
}

}  // namespace
}  // namespace reconfig::geometry
