// Fuzzing the loaders: mutated and truncated versions of valid files must either load as a
// valid-index mesh or throw InputError; never crash, hang, or throw anything else.
// The default run takes about a second. For a longer campaign:
//   RECONFIG_FUZZ_TRIALS=100000 RECONFIG_FUZZ_SEED=7 geometry_tests --gtest_filter='LoadMeshFuzz.*'

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "glb_file.h"
#include "mesh_test_helpers.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/geometry/save_mesh.h"
#include "support/test_data.h"
#include "support/text_mutation.h"

namespace reconfig::geometry {
namespace {

using reconfig::testing::glb;

struct Seed {
  std::string extension;
  std::string bytes;
};

std::vector<Seed> seeds() {
  const Mesh box = make_box({1, 2, 3});
  const Mesh sphere = make_sphere(1, 1);
  const auto dir = reconfig::testing::fresh_temp_dir();
  std::vector<Seed> out;
  save_obj(dir / "s.obj", sphere);
  out.push_back({"obj", testing::read_bytes((dir / "s.obj").string())});
  out.push_back({"obj",
                 "# quads, normals, texture coordinates, groups\no box\nv -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\n"
                 "v -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 -1\nvn 0 0 1\n"
                 "g bottom\nf 1/1/1 3/2/1 4/3/1 2/1/1\ng top\nf 5/1/2 6/2/2 8/3/2 7/1/2\nf 1//1 2//1 6//1 5//1\n"
                 "f -6 -2 -1 -5\nf 1 5 7 3\nf 2 4 8 6\n"});
  save_stl(dir / "b.stl", box, true);
  out.push_back({"stl", testing::read_bytes((dir / "b.stl").string())});
  save_stl(dir / "a.stl", box, false);
  out.push_back({"stl", testing::read_bytes((dir / "a.stl").string())});
  out.push_back({"ply", testing::ply_text(box)});
  {  // binary PLY with a quad, an extra property and an extra element
    std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                      "property float z\nproperty uchar red\nelement face 2\nproperty list uchar int vertex_indices\n"
                      "element edge 1\nproperty int a\nproperty int b\nend_header\n";
    const float corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 1}};
    for (const auto& c : corners) {
      ply.append(reinterpret_cast<const char*>(c), sizeof c);
      ply.push_back(static_cast<char>(200));
    }
    const std::int32_t quad[4] = {0, 1, 2, 3}, tri[3] = {0, 2, 1};
    ply.push_back(4);
    ply.append(reinterpret_cast<const char*>(quad), sizeof quad);
    ply.push_back(3);
    ply.append(reinterpret_cast<const char*>(tri), sizeof tri);
    const std::int32_t edge[2] = {0, 1};
    ply.append(reinterpret_cast<const char*>(edge), sizeof edge);
    out.push_back({"ply", ply});
  }
  out.push_back({"off", testing::off_text(sphere)});
  out.push_back({"off", "COFF 4 4 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n0 0 1 1 1 1 1\n"
                        "3 0 2 1\n3 0 1 3\n3 0 3 2\n4 1 2 3 0\n"});
  {  // glTF with an embedded buffer: a tetrahedron placed by a node with a translation
    const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const std::uint16_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    std::string buffer(reinterpret_cast<const char*>(positions), sizeof positions);
    buffer.append(reinterpret_cast<const char*>(indices), sizeof indices);
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string base64;
    for (std::size_t i = 0; i < buffer.size(); i += 3) {  // 72 bytes: no padding needed
      const unsigned n = (static_cast<unsigned char>(buffer[i]) << 16) |
                         (static_cast<unsigned char>(buffer[i + 1]) << 8) | static_cast<unsigned char>(buffer[i + 2]);
      for (int k = 3; k >= 0; --k) base64 += table[(n >> (6 * k)) & 63];
    }
    const auto gltf = [](const std::string& uri_field) {
      return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0,"translation":[5,0,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
"buffers":[{"byteLength":72)" + uri_field + R"(}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,1]},
{"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}]})";
    };
    out.push_back({"gltf", gltf(R"(,"uri":"data:application/octet-stream;base64,)" + base64 + "\"")});
    out.push_back({"glb", glb(gltf(""), buffer)});  // the same in a GLB's JSON and BIN chunks
  }
  return out;
}

std::string mutate(const std::string& original, std::mt19937& rng) {
  static const std::vector<std::string> tokens = {"-1",   "0",    "4294967295", "99999999999", "1e308", "-1e400",
                                                  "nan",  "inf",  "#",          "\n",          " ",     "/",
                                                  "f",    "v",    "3",          "255",         "-",     ".",
                                                  "\0",   "end_header\n", "endsolid", "facet normal", "OFF", "vn",
                                                  // glTF: URIs out of the folder, deep nesting, node cycles, lengths
                                                  "../",  "/etc/passwd", "%2e%2e/", "data:,", "\"uri\":\"../x.bin\",",
                                                  "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[",
                                                  "\"children\":[0],", "4294967280", "glTF"};
  return reconfig::testing::mutate_text(original, rng, tokens);
}

/// Loads `bytes`; fails the test unless it is a valid-index mesh or an InputError. Returns
/// whether it loaded.
bool expect_mesh_or_input_error(const std::string& bytes, const std::string& extension, int trial) {
  try {
    const Mesh mesh = load_mesh_from_memory(bytes, extension);
    EXPECT_GT(mesh.face_count(), 0) << "trial " << trial;
    EXPECT_TRUE(mesh.V.allFinite()) << "trial " << trial;
    EXPECT_TRUE((mesh.F.array() >= 0).all() && (mesh.F.array() < mesh.vertex_count()).all()) << "trial " << trial;
    MeshCheckOptions options;
    options.check_self_intersections = trial % 16 == 0;
    const MeshReport report = check_mesh(mesh, options);
    EXPECT_FALSE(report.out_of_range_faces.any());
    EXPECT_FALSE(report.summary().empty());
    return true;
  } catch (const InputError&) {
    return false;  // expected for most mutations
  } catch (const std::exception& e) {
    ADD_FAILURE() << "trial " << trial << " (" << extension << "): not an InputError: " << e.what();
    return false;
  }
}

TEST(LoadMeshFuzz, MutatedFilesLoadOrThrowInputError) {
  const std::vector<Seed> all = seeds();
  for (const Seed& seed : all) ASSERT_NO_THROW(load_mesh_from_memory(seed.bytes, seed.extension)) << seed.extension;
  std::mt19937 rng(static_cast<unsigned>(reconfig::testing::fuzz_setting("RECONFIG_FUZZ_SEED", 12345)));
  const auto start = std::chrono::steady_clock::now();
  int trials = 0, loaded = 0;
  const int max_trials = reconfig::testing::fuzz_setting("RECONFIG_FUZZ_TRIALS", 10000);
  for (; trials < max_trials; ++trials) {
    const Seed& seed = all[static_cast<std::size_t>(trials) % all.size()];
    const std::string bytes = mutate(seed.bytes, rng);
    try {
      loaded += expect_mesh_or_input_error(bytes, seed.extension, trials);
      if (::testing::Test::HasFailure()) return;
    } catch (...) {
      FAIL() << "trial " << trials << " threw out of the checker";
    }
    if (!std::getenv("RECONFIG_FUZZ_TRIALS") && std::chrono::steady_clock::now() - start > std::chrono::milliseconds(1000)) break;
  }
  std::printf("[ fuzz     ] %d mutated files, %d loaded as meshes\n", trials, loaded);
  EXPECT_GE(trials, 800) << "the loaders are too slow to fuzz enough in the time budget";
}

TEST(LoadMeshFuzz, EveryTruncationOfEachSeed) {
  for (const Seed& seed : seeds()) {
    const std::size_t step = std::max<std::size_t>(1, seed.bytes.size() / 80);
    for (std::size_t length = 0; length < seed.bytes.size(); length += step) {
      expect_mesh_or_input_error(seed.bytes.substr(0, length), seed.extension, static_cast<int>(length));
      if (::testing::Test::HasFailure()) return;
    }
  }
}

TEST(LoadMeshFuzz, WrongExtensionHintsAreHandled) {
  const std::vector<Seed> all = seeds();
  int trial = 0;
  for (const Seed& seed : all)
    for (const char* hint : {"obj", "stl", "ply", "off", "glb", "gltf", "xyz", ""}) {
      expect_mesh_or_input_error(seed.bytes, hint, trial++);
      if (::testing::Test::HasFailure()) return;
    }
}

/// 72 bytes: a tetrahedron of edge `size` (float positions), then its uint16 indices.
std::string tetrahedron_buffer(float size) {
  const float positions[12] = {0, 0, 0, size, 0, 0, 0, size, 0, 0, 0, size};
  const std::uint16_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  std::string buffer(reinterpret_cast<const char*>(positions), sizeof positions);
  return buffer.append(reinterpret_cast<const char*>(indices), sizeof indices);
}

/// glTF buffer URIs made of hostile pieces (FIFOs, devices, loops, links out, `..`, absolute and
/// percent-encoded paths) never hang or crash, and a buffer outside the glTF's folder is never
/// read unless allowed.
TEST(LoadMeshFuzz, HostileBufferUrisNeverHangOrLeaveTheFolder) {
  namespace fs = std::filesystem;
  const fs::path root = reconfig::testing::fresh_temp_dir();
  const fs::path dir = root / "design";
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "in.bin", std::ios::binary) << tetrahedron_buffer(1);
  std::ofstream(root / "out.bin", std::ios::binary) << tetrahedron_buffer(10);
  ASSERT_EQ(::mkfifo((dir / "fifo.bin").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.bin");
  fs::create_symlink("loop.bin", dir / "loop.bin");
  fs::create_symlink("..", dir / "sub" / "up");
  fs::create_symlink(root / "out.bin", dir / "link.bin");
  const std::vector<std::string> pieces = {"..", ".", "sub", "up", "in.bin", "out.bin", "fifo.bin", "zero.bin",
                                           "loop.bin", "link.bin", "%2e%2e", "%2F", "", "design", "/dev/urandom",
                                           root.string(), "sub/in.bin", "sub/up/out.bin", "../out.bin", "missing.bin"};
  std::mt19937 rng(static_cast<unsigned>(reconfig::testing::fuzz_setting("RECONFIG_FUZZ_SEED", 25)));
  const int trials = reconfig::testing::fuzz_setting("RECONFIG_FUZZ_TRIALS", 400);
  int loaded = 0, outside = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int trial = 0; trial < trials; ++trial) {
    std::string uri;
    for (int k = 0, n = 1 + static_cast<int>(rng() % 3); k < n; ++k) uri += (k ? "/" : "") + pieces[rng() % pieces.size()];
    const fs::path file = dir / "m.gltf";
    std::ofstream(file) << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"buffers":[{"byteLength":72,"uri":")" +
                               uri + R"("}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
{"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}]})";
    const bool allowed = rng() % 4 == 0;
    try {
      const Mesh mesh = load_mesh(file, {.allow_outside_paths = allowed});
      ++loaded;
      const bool from_outside = mesh.V.maxCoeff() > 5;
      outside += from_outside;
      EXPECT_TRUE(allowed || !from_outside) << "read a buffer outside the folder through \"" << uri << "\"";
    } catch (const InputError& error) {
      EXPECT_LT(std::string(error.what()).size(), 3 * kMaxInputErrorPart);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ fuzz     ] %d hostile buffer URIs in %.2f s: %d loaded, %d of them from outside (allowed)\n", trials,
              seconds, loaded, outside);
  EXPECT_GT(loaded, 0);
}

}  // namespace
}  // namespace reconfig::geometry
