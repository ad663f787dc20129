#include "reconfig/geometry/load_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

#include "mesh_test_helpers.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/geometry/save_mesh.h"
#include "support/test_data.h"

namespace reconfig::geometry {
namespace {

namespace fs = std::filesystem;
using reconfig::testing::cgal_mesh;
using reconfig::testing::fresh_temp_dir;
using testing::canonical;
using testing::same_mesh;
using testing::write_bytes;

MeshCheckOptions fast() {
  MeshCheckOptions options;
  options.check_self_intersections = false;
  return options;
}

/// Runs `load` and returns the InputError it throws (fails the test if it does not throw).
template <class Load>
InputError error_of(Load load) {
  try {
    load();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("", "", "");
}

TEST(LoadMesh, ReadsAClosedOff) {
  const Mesh cube = load_mesh(cgal_mesh("cube.off"));
  EXPECT_EQ(cube.vertex_count(), 8);
  EXPECT_EQ(cube.face_count(), 12);
  EXPECT_TRUE(check_mesh(cube).is_valid_solid()) << check_mesh(cube).summary();
  EXPECT_DOUBLE_EQ(mass_properties(cube).volume, 8);
}

TEST(LoadMesh, MissingFileNamesTheFile) {
  const fs::path path = fresh_temp_dir() / "nope.obj";
  const InputError e = error_of([&] { load_mesh(path); });
  EXPECT_EQ(e.file(), path.string());
  EXPECT_EQ(e.message(), "file not found");
}

TEST(LoadMesh, UnreadableContentNamesTheFileAndGivesAssimpsReason) {
  const fs::path dir = fresh_temp_dir();
  write_bytes((dir / "junk.stl").string(), "this is not an stl file at all");
  const InputError e = error_of([&] { load_mesh(dir / "junk.stl"); });
  EXPECT_EQ(e.file(), (dir / "junk.stl").string());
  EXPECT_FALSE(e.message().empty());

  write_bytes((dir / "mesh.unknownformat").string(), "v 0 0 0\n");
  EXPECT_EQ(error_of([&] { load_mesh(dir / "mesh.unknownformat"); }).file(), (dir / "mesh.unknownformat").string());
  write_bytes((dir / "empty.obj").string(), "");
  EXPECT_EQ(error_of([&] { load_mesh(dir / "empty.obj"); }).file(), (dir / "empty.obj").string());
  EXPECT_EQ(error_of([&] { load_mesh(dir); }).file(), dir.string());
}

TEST(LoadMesh, FileWithoutTrianglesIsAnError) {
  const InputError e = error_of([] { load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n", "obj"); });
  EXPECT_NE(std::string(e.what()).find("no triangles"), std::string::npos) << e.what();
}

TEST(LoadMesh, OutOfRangeIndexIsAnError) {
  error_of([] { load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "obj"); });
  const InputError too_big = error_of([] { load_mesh_from_memory("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "off"); });
  EXPECT_STREQ(too_big.what(), "line 6, face 0: vertex index 7 out of range (3 vertices)");
  const InputError negative = error_of([] { load_mesh_from_memory("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "off"); });
  EXPECT_EQ(negative.location(), "line 6, face 0");
  const fs::path dir = fresh_temp_dir();
  write_bytes((dir / "bad.off").string(), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_EQ(error_of([&] { load_mesh(dir / "bad.off"); }).file(), (dir / "bad.off").string());
}

TEST(LoadMesh, ObjReaderHandlesTheUsualForms) {
  // Corner forms v, v/vt, v//vn, v/vt/vn; negative (relative) indices; a continued line; a quad;
  // ignored statements; CRLF line ends; extra vertex values (a color).
  const std::string obj =
      "mtllib parts.mtl\r\no tet\r\nv 0 0 0 1 0 0\r\nv 0.1 0 0\r\nv 0 0.1 0\r\nv 0 0 0.1\r\n"
      "vt 0 0\r\nvn 0 0 1\r\ns off\r\nusemtl wood\r\n"
      "f 1/1 3/1 2/1\r\nf 1//1 2//1 \\\r\n 4//1\r\nf -4/1/1 -1/1/1 -2/1/1\r\nf 2 3 4\r\nl 1 2\r\n"
      "v 5 5 5\nv 6 5 5\nv 6 6 5\nv 5 6 5\nf -4 -3 -2 -1\n";
  const Mesh mesh = load_mesh_from_memory(obj, "obj");
  EXPECT_EQ(mesh.vertex_count(), 8);
  EXPECT_EQ(mesh.face_count(), 6);
  EXPECT_EQ(mesh.V(1, 0), 0.1);  // the double nearest to 0.1
  const MeshReport report = check_mesh(mesh);
  EXPECT_EQ(report.component_count, 2);
  EXPECT_EQ(report.boundary_edges.count, 4);  // the square is open, the tetrahedron closed
  EXPECT_TRUE(report.is_oriented());
  Mesh tet = mesh;
  tet.F = mesh.F.topRows(4);
  EXPECT_NEAR(mass_properties(tet).volume, 1e-3 / 6, 1e-3 * 1e-12);

  EXPECT_STREQ(error_of([] { load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 0\n", "obj"); }).what(),
               "line 5: vertex index 0 out of range (3 vertices so far)");
  EXPECT_EQ(error_of([] { load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n", "obj"); }).location(),
            "line 4");
  EXPECT_EQ(error_of([] { load_mesh_from_memory("v 0 0 0\nv 1 0\n", "obj"); }).location(), "line 2");
  EXPECT_EQ(error_of([] { load_mesh_from_memory("v 0 0 0\nv 1 0 inf\n", "obj"); }).location(), "line 2, vertex 2");
  EXPECT_EQ(error_of([] { load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "obj"); }).location(), "line 4");
  EXPECT_EQ(error_of([] { load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/1\n", "obj"); }).location(),
            "line 4");
}

TEST(LoadMesh, OffReaderHandlesTheUsualVariants) {
  // Counts on the keyword line, comments, blank lines, colors after vertices and faces,
  // an edge and a point element to skip, exact doubles.
  const std::string off =
      "COFF 4 6 0 # a tetrahedron\n\n"
      "0 0 0 255 0 0 255\n0.1 0 0 0 255 0 255\n# comment line\n0 0.1 0 0 0 255 255\n0 0 0.1 9 9 9 9\n"
      "3 0 2 1 0.5 0.5 0.5\n3 0 1 3\n3 0 3 2\n3 1 2 3\n2 0 1\n1 3\n";
  const Mesh tet = load_mesh_from_memory(off, "off");
  EXPECT_EQ(tet.vertex_count(), 4);
  EXPECT_EQ(tet.face_count(), 4);
  EXPECT_EQ(tet.V(1, 0), 0.1);  // the double nearest to 0.1, not the float
  EXPECT_TRUE(check_mesh(tet).is_valid_solid()) << check_mesh(tet).summary();
  // Keyword and counts on separate lines, headerless.
  EXPECT_EQ(load_mesh_from_memory("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "off").face_count(), 1);
  EXPECT_EQ(load_mesh_from_memory("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "off").face_count(), 1);
  // Errors name the line.
  EXPECT_EQ(error_of([] { load_mesh_from_memory("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "off"); }).location(),
            "line 4, vertex 1");
  EXPECT_EQ(error_of([] { load_mesh_from_memory("OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n", "off"); }).location(),
            "line 5, vertex 2");
  EXPECT_EQ(error_of([] { load_mesh_from_memory("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "off"); }).location(),
            "line 6");
  error_of([] { load_mesh_from_memory("4OFF\n3 1 0\n0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 2\n", "off"); });
  error_of([] { load_mesh_from_memory("OFF BINARY\n", "off"); });
}

/// A prism of height 1 over `outline` (counter-clockwise), written as OFF with each cap one
/// polygon, and loaded back.
Mesh prism(const std::vector<Eigen::Vector2d>& outline) {
  const int n = static_cast<int>(outline.size());
  std::ostringstream off;
  off.precision(17);
  off << "OFF\n" << 2 * n << " " << n + 2 << " 0\n";
  for (int z = 0; z < 2; ++z)
    for (const auto& p : outline) off << p.x() << " " << p.y() << " " << z << "\n";
  off << n;
  for (int i = n - 1; i >= 0; --i) off << " " << i;
  off << "\n" << n;
  for (int i = 0; i < n; ++i) off << " " << n + i;
  off << "\n";
  for (int i = 0; i < n; ++i) off << "4 " << i << " " << (i + 1) % n << " " << n + (i + 1) % n << " " << n + i << "\n";
  return load_mesh_from_memory(off.str(), "off");
}

TEST(LoadMesh, OffKeepsLargeAndConcavePolygons) {
  // A prism over a 12-gon (caps with 12 corners) and over a concave L-shaped hexagon.
  std::vector<Eigen::Vector2d> circle;
  for (int i = 0; i < 12; ++i) circle.emplace_back(std::cos(i * M_PI / 6), std::sin(i * M_PI / 6));
  const Mesh round = prism(circle);
  EXPECT_EQ(round.face_count(), 2 * 10 + 2 * 12);
  EXPECT_TRUE(check_mesh(round).is_valid_solid()) << check_mesh(round).summary();
  const Mesh ell = prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});  // area 3
  const MeshReport report = check_mesh(ell);
  EXPECT_TRUE(report.is_valid_solid()) << report.summary();  // a fan from corner 0 would fold over
  EXPECT_NEAR(mass_properties(ell).volume, 3, 1e-12);
}

TEST(LoadMesh, NonFiniteCoordinateNamesTheVertex) {
  // A binary STL with one triangle whose second corner has a NaN y.
  std::string bytes(80, ' ');
  auto put = [&](std::uint32_t bits) {
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>((bits >> (8 * i)) & 0xff));
  };
  auto put_float = [&](float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    put(bits);
  };
  put(1);
  for (float f : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f, 1.f, 0.f})
    put_float(f);
  bytes += std::string(2, '\0');
  const InputError e = error_of([&] { load_mesh_from_memory(bytes, "stl"); });
  EXPECT_EQ(e.location(), "vertex 1") << e.what();
  EXPECT_EQ(e.message(), "coordinate is NaN or infinite");
}

TEST(LoadMesh, WeldsObjCornersWithNormalsAcrossObjectsIntoOneClosedMesh) {
  // A tetrahedron written as two objects, with per-face normals so Assimp keeps corners apart.
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
      "vn 0 0 -1\nvn 0 -1 0\nvn -1 0 0\nvn 1 1 1\n"
      "o first\nf 1//1 3//1 2//1\nf 1//2 2//2 4//2\n"
      "o second\nf 1//3 4//3 3//3\nf 2//4 3//4 4//4\n";
  const Mesh tet = load_mesh_from_memory(obj, ".OBJ");
  EXPECT_EQ(tet.vertex_count(), 4);
  EXPECT_EQ(tet.face_count(), 4);
  const MeshReport report = check_mesh(tet);
  EXPECT_TRUE(report.is_valid_solid()) << report.summary();
  EXPECT_DOUBLE_EQ(mass_properties(tet).volume, 1.0 / 6);
}

TEST(LoadMesh, TriangulatesPolygons) {
  const std::string off = "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n-1 1 1\n1 1 1\n"
                          "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
  const Mesh cube = load_mesh_from_memory(off, "off");
  EXPECT_EQ(cube.vertex_count(), 8);
  EXPECT_EQ(cube.face_count(), 12);
  EXPECT_TRUE(check_mesh(cube).is_valid_solid()) << check_mesh(cube).summary();
  EXPECT_DOUBLE_EQ(mass_properties(cube).volume, 8);
}

TEST(LoadMesh, OffTriangulatesRandomStarShapedPolygons) {
  // Oracle: a prism of height 1 over a random star-shaped (mostly concave) polygon is a valid
  // solid whose volume is the polygon's area (shoelace formula).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> radius(0.2, 1.0), jitter(0.1, 0.9);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 4 + trial % 27;
    std::vector<Eigen::Vector2d> outline;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * M_PI * (i + jitter(rng)) / n, r = radius(rng);
      outline.emplace_back(r * std::cos(angle), r * std::sin(angle));
    }
    double area = 0;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d& p = outline[static_cast<std::size_t>(i)];
      const Eigen::Vector2d& q = outline[static_cast<std::size_t>((i + 1) % n)];
      area += (p.x() * q.y() - q.x() * p.y()) / 2;
    }
    const Mesh mesh = prism(outline);
    SCOPED_TRACE(trial);
    EXPECT_EQ(mesh.face_count(), 2 * (n - 2) + 2 * n);
    const MeshReport report = check_mesh(mesh);
    EXPECT_TRUE(report.is_valid_solid()) << report.summary();
    EXPECT_NEAR(mass_properties(mesh).volume, area, 1e-12);
  }
}

// --- PLY ------------------------------------------------------------------------------------

/// Appends `value` as `T` in little- or big-endian byte order.
template <class T>
void put(std::string& bytes, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian) std::reverse(raw, raw + sizeof(T));
  bytes.append(raw, sizeof(T));
}

/// A unit cube as binary PLY with quads, extra vertex properties and an extra element.
std::string binary_ply_cube(bool big_endian) {
  std::string bytes = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\ncomment made by a test\nelement vertex 8\nproperty double x\nproperty float nx\n"
                      "property double y\nproperty double z\nproperty uchar red\nelement face 6\n"
                      "property list uchar uint vertex_indices\nproperty list int float texcoord\n"
                      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for (int i = 0; i < 8; ++i) {
    put<double>(bytes, i & 1, big_endian);
    put<float>(bytes, 0.5f, big_endian);
    put<double>(bytes, (i >> 1) & 1, big_endian);
    put<double>(bytes, (i >> 2) & 1, big_endian);
    put<std::uint8_t>(bytes, 200, big_endian);
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& quad : quads) {
    put<std::uint8_t>(bytes, 4, big_endian);
    for (int v : quad) put<std::uint32_t>(bytes, static_cast<std::uint32_t>(v), big_endian);
    put<std::int32_t>(bytes, 2, big_endian);
    put<float>(bytes, 0.25f, big_endian);
    put<float>(bytes, 0.75f, big_endian);
  }
  put<std::int32_t>(bytes, 0, big_endian);
  put<std::int32_t>(bytes, 1, big_endian);
  return bytes;
}

TEST(LoadMesh, PlyBinaryBothEndiannesses) {
  for (bool big_endian : {false, true}) {
    SCOPED_TRACE(big_endian);
    const Mesh cube = load_mesh_from_memory(binary_ply_cube(big_endian), "ply");
    EXPECT_EQ(cube.vertex_count(), 8);
    EXPECT_EQ(cube.face_count(), 12);
    EXPECT_TRUE(check_mesh(cube).is_valid_solid()) << check_mesh(cube).summary();
    EXPECT_DOUBLE_EQ(mass_properties(cube).volume, 1);
    // Every truncation of the data is an error, not a crash.
    const std::string full = binary_ply_cube(big_endian);
    const std::size_t data = full.find("end_header\n") + 11;
    for (std::size_t length = data; length + 8 < full.size(); length += 7)
      error_of([&] { load_mesh_from_memory(full.substr(0, length), "ply"); });
  }
}

TEST(LoadMesh, PlyErrorsNameTheElement) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(load_mesh_from_memory(header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "ply").face_count(), 1);
  EXPECT_STREQ(error_of([&] { load_mesh_from_memory(header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "ply"); }).what(),
               "face 0: vertex index 3 out of range (3 vertices)");
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n", "ply"); }).location(),
            "face 0");
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(header + "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "ply"); }).location(),
            "vertex 1");
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(header + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "ply"); }).location(),
            "face 0");
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(header + "0 0 0\n1 0 0\n0 x 0\n3 0 1 2\n", "ply"); }).location(),
            "vertex 2");
  // The header that made Assimp 5.2 loop forever.
  error_of([] { load_mesh_from_memory("ply\nformat ascii 1.0\nelement face 12\nproperty list", "ply"); });
  EXPECT_EQ(error_of([] { load_mesh_from_memory("ply\nformat ascii 1.0\nelement vertex 3\nproperty float\n", "ply"); })
                .location(),
            "header line 4");
}

// --- glTF: one mesh placed by two nodes, one of them mirrored. ------------------------------

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const auto n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                   static_cast<unsigned char>(bytes[i + 2]);
    for (int k = 3; k >= 0; --k) out += table[(n >> (6 * k)) & 63];
  }
  if (i + 1 == bytes.size()) {
    const auto n = static_cast<unsigned char>(bytes[i]) << 16;
    out += std::string{table[(n >> 18) & 63], table[(n >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const auto n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += std::string{table[(n >> 18) & 63], table[(n >> 12) & 63], table[(n >> 6) & 63], '='};
  }
  return out;
}

/// Buffer of a unit right tetrahedron: 4 float3 positions then 12 uint16 indices (outward).
std::string tetrahedron_buffer() {
  std::string bytes;
  const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::uint16_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  bytes.append(reinterpret_cast<const char*>(positions), sizeof positions);
  bytes.append(reinterpret_cast<const char*>(indices), sizeof indices);
  return bytes;
}

std::string gltf_json(const std::string& buffer_uri_field) {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],
  "nodes":[{"mesh":0,"translation":[5,0,0]},{"mesh":0,"scale":[-1,1,1],"translation":[-5,0,0]}],
  "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
  "buffers":[{"byteLength":72)" +
         buffer_uri_field + R"(}],
  "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],
  "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,1]},
               {"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}]})";
}

void expect_two_placed_tetrahedra(const Mesh& mesh) {
  EXPECT_EQ(mesh.vertex_count(), 8);
  EXPECT_EQ(mesh.face_count(), 8);
  const MeshReport report = check_mesh(mesh);
  EXPECT_TRUE(report.is_valid_solid()) << report.summary();  // the mirrored copy still points out
  EXPECT_EQ(report.component_count, 2);
  const MassProperties mp = mass_properties(mesh);
  EXPECT_NEAR(mp.volume, 2.0 / 6, 1e-12);
  EXPECT_NEAR(mp.bounds.min().x(), -6, 1e-12);
  EXPECT_NEAR(mp.bounds.max().x(), 6, 1e-12);
}

TEST(LoadMesh, GltfAppliesNodeTransformsAndKeepsMirroredPartsOutward) {
  const std::string json =
      gltf_json(R"(,"uri":"data:application/octet-stream;base64,)" + base64(tetrahedron_buffer()) + "\"");
  expect_two_placed_tetrahedra(load_mesh_from_memory(json, "gltf"));

  // The same with an external .bin next to the .gltf.
  const fs::path dir = fresh_temp_dir();
  write_bytes((dir / "tets.bin").string(), tetrahedron_buffer());
  write_bytes((dir / "tets.gltf").string(), gltf_json(R"(,"uri":"tets.bin")"));
  expect_two_placed_tetrahedra(load_mesh(dir / "tets.gltf"));
}

TEST(LoadMesh, GlbWithBinaryChunk) {
  std::string json = gltf_json("");
  while (json.size() % 4) json += ' ';
  const std::string bin = tetrahedron_buffer();  // 72 bytes, already a multiple of 4
  std::string glb;
  auto put = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) glb.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  };
  glb += "glTF";
  put(2);
  put(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  put(static_cast<std::uint32_t>(json.size()));
  glb += "JSON";
  glb += json;
  put(static_cast<std::uint32_t>(bin.size()));
  glb += std::string("BIN\0", 4);
  glb += bin;
  expect_two_placed_tetrahedra(load_mesh_from_memory(glb, "glb"));
}

// --- Round trips of real meshes through our writers and PLY. --------------------------------

TEST(LoadMesh, CgalMeshesRoundTripThroughObjStlAndPly) {
  const fs::path dir = fresh_temp_dir();
  for (const char* name : {"elephant.off", "fandisk.off"}) {
    SCOPED_TRACE(name);
    const Mesh original = load_mesh(cgal_mesh(name));
    ASSERT_TRUE(check_mesh(original, fast()).is_closed());
    save_obj(dir / "m.obj", original);
    save_stl(dir / "m.stl", original, true);
    save_stl(dir / "a.stl", original, false);
    write_bytes((dir / "m.ply").string(), testing::ply_text(original));
    for (const char* file : {"m.obj", "m.stl", "a.stl", "m.ply"}) {
      SCOPED_TRACE(file);
      const Mesh back = load_mesh(dir / file);
      // Our OBJ and PLY readers are exact; Assimp reads STL as floats, and its text parser may
      // miss the nearest float by an ulp.
      if (std::string(file) == "m.ply" || std::string(file) == "m.obj")
        EXPECT_TRUE(same_mesh(back, original));
      else if (std::string(file) == "m.stl")
        EXPECT_TRUE(same_mesh(back, testing::rounded_to_float(original)));
      else
        EXPECT_TRUE(testing::same_faces_within(back, original, 1e-6 * original.V.cwiseAbs().maxCoeff()));
      EXPECT_TRUE(check_mesh(back, fast()).is_closed());
    }
  }
}

TEST(LoadMesh, ArmadilloLoadsAsAClosedOutwardMesh) {
  const Mesh armadillo = load_mesh(cgal_mesh("armadillo.off"));
  EXPECT_EQ(armadillo.vertex_count(), 26002);
  EXPECT_EQ(armadillo.face_count(), 52000);
  const MeshReport report = check_mesh(armadillo, fast());
  EXPECT_TRUE(report.is_closed()) << report.summary();
  EXPECT_TRUE(report.is_manifold()) << report.summary();
  EXPECT_TRUE(report.is_oriented()) << report.summary();
  EXPECT_TRUE(report.is_outward()) << report.summary();
  EXPECT_GT(mass_properties(armadillo).volume, 0);
}

}  // namespace
}  // namespace reconfig::geometry
