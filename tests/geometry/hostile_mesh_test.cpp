// glTF and GLB files made to crash Assimp, make it allocate gigabytes or read files outside
// the design (issue 25): each is refused before Assimp sees it, naming the place.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "glb_file.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/load_mesh.h"
#include "support/test_data.h"

namespace reconfig::geometry {
namespace {

using reconfig::testing::append_u32;
using reconfig::testing::glb;

/// `text` with the first `from` replaced by `to`, built by appending (GCC 12 warns falsely of
/// overlapping copies, -Wrestrict, on std::string::replace with a literal here).
std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  std::string out = text.substr(0, at);
  out.append(to);
  out.append(text, at + from.size(), std::string::npos);
  return out;
}

namespace fs = std::filesystem;

/// A tetrahedron: 4 float positions, then 12 uint16 indices (72 bytes).
std::string tetrahedron_buffer() {
  const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::uint16_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  std::string buffer(reinterpret_cast<const char*>(positions), sizeof positions);
  return buffer.append(reinterpret_cast<const char*>(indices), sizeof indices);
}

/// A glTF of the tetrahedron whose buffer is `buffer` (a JSON object's members), with `nodes`
/// (a JSON array; node 0 is the scene's root and should carry the mesh) and extra members.
std::string gltf(const std::string& buffer, const std::string& nodes = R"([{"mesh":0}])",
                 const std::string& extra = "") {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" + nodes +
         R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"buffers":[{)" + buffer +
         R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,1]},
{"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}])" + extra + "}";
}

std::string embedded() {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const std::string buffer = tetrahedron_buffer();
  std::string base64;
  for (std::size_t i = 0; i < buffer.size(); i += 3) {
    const unsigned n = (static_cast<unsigned char>(buffer[i]) << 16) |
                       (static_cast<unsigned char>(buffer[i + 1]) << 8) | static_cast<unsigned char>(buffer[i + 2]);
    for (int k = 3; k >= 0; --k) base64 += table[(n >> (6 * k)) & 63];
  }
  return R"("byteLength":72,"uri":"data:application/octet-stream;base64,)" + base64 + "\"";
}

InputError error_of(const std::function<void()>& load) {
  try {
    load();
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "loaded";
  return InputError("", "", "");
}

fs::path write(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

TEST(HostileMesh, ValidGlbLoads) {
  EXPECT_EQ(load_mesh_from_memory(glb(gltf(R"("byteLength":72)"), tetrahedron_buffer()), "glb").face_count(), 4);
}

TEST(HostileMesh, AGlbChunkLongerThanTheFileIsRefusedBeforeAllocating) {
  std::string tiny = "glTF";  // 22 bytes declaring a 4 GB JSON chunk
  append_u32(tiny, 2);
  append_u32(tiny, 22);
  append_u32(tiny, 0xFFFFFFF0u);
  tiny += "JSON{}";
  const auto start = std::chrono::steady_clock::now();
  const InputError error = error_of([&] { load_mesh_from_memory(tiny, "glb"); });
  EXPECT_EQ(error.location(), "GLB chunk 0");
  EXPECT_EQ(error.message(), "declares 4294967280 bytes, the file has 2 after the chunk header");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(500));
  std::string longer = glb(gltf(R"("byteLength":72)"), tetrahedron_buffer());
  longer[8] = static_cast<char>(0xff);  // the header's total length
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(longer, "glb"); }).location(), "GLB header");
}

TEST(HostileMesh, ABufferLongerThanItsDataIsRefused) {
  const InputError error = error_of([&] {
    load_mesh_from_memory(glb(gltf(R"("byteLength":4000000000)"), tetrahedron_buffer()), "glb");
  });
  EXPECT_EQ(error.location(), "buffers[0].byteLength");
  EXPECT_EQ(error.message(), "declares 4000000000 bytes, its data has 72");
  const std::string view_beyond = glb(gltf(R"("byteLength":72)"), tetrahedron_buffer());
  const std::string edited = replaced(view_beyond, R"("byteOffset":48,"byteLength":24)", R"("byteOffset":48,"byteLength":99)");
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(edited, "glb"); }).location(), "bufferViews[1]");
  // An accessor without a view is zeros: Assimp allocates them.
  const std::string zeros =
      replaced(replaced(gltf(embedded()), R"({"bufferView":1,)", "{"), R"("count":12,)", R"("count":4000000000,)");
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(zeros, "gltf"); }).location(), "accessors[1].count");
}

/// Nodes 0 → 1 → … → depth-1, the last one carrying the mesh.
std::string chain(int depth) {
  std::string nodes = "[";
  for (int i = 0; i + 1 < depth; ++i) nodes += R"({"children":[)" + std::to_string(i + 1) + "]},";
  return nodes + R"({"mesh":0}])";
}

TEST(HostileMesh, ANodeChainTooDeepForAssimpIsRefused) {
  EXPECT_EQ(load_mesh_from_memory(gltf(embedded(), chain(200)), "gltf").face_count(), 4);
  const auto start = std::chrono::steady_clock::now();
  const InputError error = error_of([&] { load_mesh_from_memory(gltf(embedded(), chain(20'000)), "gltf"); });
  EXPECT_NE(error.message().find("deeper than 256 levels"), std::string::npos) << error.what();
  EXPECT_EQ(error.location().rfind("nodes[", 0), 0u) << error.location();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  const InputError cycle = error_of([&] {
    load_mesh_from_memory(gltf(embedded(), R"([{"mesh":0,"children":[1]},{"children":[0]}])"), "gltf");
  });
  EXPECT_EQ(cycle.message(), "the node is its own ancestor (a cycle)");
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(gltf(embedded(), R"([{"mesh":0,"children":[7]}])"), "gltf"); })
                .location(),
            "nodes[0].children[0]");
}

TEST(HostileMesh, BufferAndImageUrisMustStayInTheFolder) {
  const fs::path outside = testing::fresh_temp_dir();
  const fs::path dir = outside / "design";
  fs::create_directories(dir);
  write(outside / "secret.bin", tetrahedron_buffer());
  for (const std::string& uri : std::vector<std::string>{"../secret.bin", (outside / "secret.bin").string(),
                                                         "%2e%2e/secret.bin", "sub/../../secret.bin"}) {
    const fs::path file = write(dir / "m.gltf", gltf(R"("byteLength":72,"uri":")" + uri + "\""));
    const InputError error = error_of([&] { load_mesh(file); });
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), "buffers[0].uri") << uri;
    EXPECT_NE(error.message().find("--allow-outside-paths"), std::string::npos) << error.what();
  }
  const fs::path file = write(dir / "m.gltf", gltf(R"("byteLength":72,"uri":"../secret.bin")"));
  EXPECT_EQ(load_mesh(file, {.allow_outside_paths = true}).face_count(), 4);
  write(dir / "inside.bin", tetrahedron_buffer());
  const std::string image = R"(,"images":[{"uri":"../../../../etc/passwd"}])";
  const fs::path with_image = write(dir / "i.gltf", gltf(R"("byteLength":72,"uri":"inside.bin")", R"([{"mesh":0}])", image));
  EXPECT_EQ(error_of([&] { load_mesh(with_image); }).location(), "images[0].uri");
  EXPECT_EQ(load_mesh(write(dir / "ok.gltf", gltf(R"("byteLength":72,"uri":"inside.bin")"))).face_count(), 4);
  // In memory, Assimp would look for the buffer in the working folder.
  EXPECT_EQ(error_of([&] { load_mesh_from_memory(gltf(R"("byteLength":72,"uri":"/etc/passwd")"), "gltf"); })
                .location(),
            "buffers[0].uri");
}

TEST(HostileMesh, AnExternalBufferMustBeARegularFileOfItsLength) {
  const fs::path dir = testing::fresh_temp_dir();
  ASSERT_EQ(::mkfifo((dir / "pipe.bin").c_str(), 0600), 0);
  const fs::path fifo = write(dir / "fifo.gltf", gltf(R"("byteLength":72,"uri":"pipe.bin")"));
  const InputError error = error_of([&] { load_mesh(fifo); });
  EXPECT_EQ(error.location(), "buffers[0].uri");
  EXPECT_NE(error.message().find("is not a regular file (a FIFO)"), std::string::npos) << error.what();
  write(dir / "short.bin", "abc");
  const fs::path shorter = write(dir / "short.gltf", gltf(R"("byteLength":72,"uri":"short.bin")"));
  EXPECT_EQ(error_of([&] { load_mesh(shorter); }).message(), "declares 72 bytes, its data has 3");
}

TEST(HostileMesh, DeviceFilesAndFifosAreRefusedAsMeshes) {
  const fs::path dir = testing::fresh_temp_dir();
  ASSERT_EQ(::mkfifo((dir / "pipe.stl").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.obj");
  fs::create_symlink("/dev/urandom", dir / "random.glb");
  fs::create_symlink("loop.ply", dir / "loop.ply");
  for (const auto& [name, message] : {std::pair{"pipe.stl", "is not a regular file (a FIFO)"},
                                      std::pair{"zero.obj", "is not a regular file (a character device)"},
                                      std::pair{"random.glb", "is not a regular file (a character device)"},
                                      std::pair{"loop.ply", "cannot read the file: Too many levels of symbolic links"}}) {
    const InputError error = error_of([&] { load_mesh(dir / name); });
    EXPECT_EQ(error.file(), (dir / name).string());
    EXPECT_EQ(error.message(), message);
  }
}

}  // namespace
}  // namespace reconfig::geometry
