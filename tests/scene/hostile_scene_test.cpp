// Scene files made to crash, hang or mislead the loader (issue 25): each is refused with the
// file and the JSON path, quickly and with a bounded message.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <nlohmann/json.hpp>

#include "reconfig/common/input_error.h"
#include "reconfig/common/read_input_file.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/geometry/save_mesh.h"
#include "reconfig/scene/scene_file.h"
#include "support/test_data.h"
#include "support/text_mutation.h"

namespace reconfig::scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// A small valid scene: a box that slides from one state to the other along a Bézier curve.
json valid_scene() {
  return json::parse(R"({
    "format": "reconfig-scene", "version": 1, "units": "m",
    "parts": [{"name": "lid", "box": {"size": [1, 0.5, 0.1]}}, {"name": "ball", "sphere": {"radius": 0.2}}],
    "states": [{"name": "closed", "poses": {"lid": {"translation": [0, 0, 0.45]}}},
               {"name": "open", "poses": {"lid": {"translation": [0, 0.2, 0.75]}}}],
    "transitions": [{"name": "unfold", "from": "closed", "to": "open", "tracks": {"lid": {"translation": [
      {"time": 0, "point": [0, 0, 0.45], "out": [0, 0.1, 0.6]},
      {"time": 1, "point": [0, 0.2, 0.75], "in": [0, 0.2, 0.6]}]}}}]})");
}

const char* kInlineLinkage = R"({"format": "reconfig-linkage", "version": 1,
  "joints": [{"name": "A", "position": [0, 0], "fixed": true}, {"name": "B", "position": [1, 0]}],
  "links": [["A", "B"]], "motor": {"center": "A", "joint": "B"}})";

/// The error parsing `text` gives, failing the test if it parses.
InputError error_of(const std::string& text) {
  try {
    parse_scene(text, fs::current_path(), "hostile.json");
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "accepted " << text.substr(0, 200);
  return InputError("", "", "");
}

InputError load_error(const fs::path& file, const SceneLoadOptions& options = {}) {
  try {
    load_scene(file, options);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "loaded " << file;
  return InputError("", "", "");
}

std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

/// `valid_scene()` as text with `"field": value` spliced in first, for values a json cannot hold.
std::string with_raw_member(const std::string& field, const std::string& value) {
  std::string text = valid_scene().dump();
  return text.insert(1, "\"" + field + "\": " + value + ", ");
}

std::string text_with(const std::function<void(json&)>& edit) {
  json document = valid_scene();
  edit(document);
  return document.dump();
}

TEST(HostileScene, DeeplyNestedVersionIsRefusedNotACrash) {
  std::string text = valid_scene().dump();
  text.replace(text.find("\"version\":1"), 11, "\"version\":" + nested(65'000));
  const InputError error = error_of(text);
  EXPECT_EQ(error.file(), "hostile.json");
  EXPECT_EQ(error.location().substr(0, 10), "version[0]");
  EXPECT_NE(error.message().find("nested deeper than 100 levels"), std::string::npos) << error.what();
}

TEST(HostileScene, NestingAtTheLimitIsParsedOn) {
  // 99 arrays inside the top-level object reach the limit of 100 levels: the version check speaks.
  std::string text = valid_scene().dump();
  text.replace(text.find("\"version\":1"), 11, "\"version\":" + nested(99));
  EXPECT_EQ(error_of(text).message(), "unsupported version: an array of 1 element (this build reads version 1)");
}

TEST(HostileScene, DeepValueInAnInlineLinkageIsRefused) {
  json linkage = json::parse(kInlineLinkage);
  const std::string text = text_with([&](json& d) {
    d["transitions"][0]["linkage"] = {{"inline", linkage}, {"motor", {{"from", 0}, {"to", 1}}},
                                      {"attach", {{{"part", "lid"}, {"link", {"A", "B"}}}}}};
  });
  std::string hostile = text;
  hostile.replace(hostile.find("\"version\":1},\"motor\""), 11, "\"version\":" + nested(65'000));  // the linkage's
  const InputError error = error_of(hostile);
  EXPECT_EQ(error.location().rfind("transitions[0].linkage.inline.version[0][0][0]", 0), 0u) << error.location();
  EXPECT_NE(error.message().find("nested deeper"), std::string::npos) << error.what();
}

TEST(HostileScene, HugeValueGivesABoundedMessage) {
  std::string huge = "[";
  for (int i = 0; i < 1'000'000; ++i) huge += "0,";
  huge += "0]";
  std::string text = valid_scene().dump();
  text.replace(text.find("\"version\":1"), 11, "\"version\":" + huge);
  const InputError error = error_of(text);
  EXPECT_EQ(error.message(), "unsupported version: an array of 1000001 elements (this build reads version 1)");
  const InputError echo = error_of(text_with([](json& d) {
    d["transitions"][0]["tracks"]["lid"]["interpolation"] = std::string(1 << 24, 'x');
  }));
  EXPECT_NE(echo.message().find("unknown interpolation"), std::string::npos);
  EXPECT_LT(std::string(echo.what()).size(), 3 * kMaxInputErrorPart);
}

TEST(HostileScene, VersionBeyondAnIntDoesNotWrapAround) {
  const InputError error = error_of(text_with([](json& d) { d["version"] = 4294967297u; }));
  EXPECT_EQ(error.location(), "version");
  EXPECT_EQ(error.message(), "unsupported version: the number 4294967297 (this build reads version 1)");
}

TEST(HostileScene, DuplicateKeysAreRefusedWithTheirPath) {
  EXPECT_EQ(error_of(with_raw_member("version", "1")).location(), "version");
  std::string text = valid_scene().dump();
  text.replace(text.find("\"radius\":0.2"), 12, "\"radius\":0.2,\"radius\":5");
  const InputError error = error_of(text);
  EXPECT_EQ(error.location(), "parts[1].sphere.radius");
  EXPECT_EQ(error.message(), "duplicate key (given twice in one object)");
}

TEST(HostileScene, ControlCharactersInNamesAreRefused) {
  const InputError part = error_of(text_with([](json& d) { d["parts"][0]["name"] = "lid\x1b[2J"; }));
  EXPECT_EQ(part.location(), "parts[0].name");
  EXPECT_EQ(part.message(), "a name must not contain control characters");
  EXPECT_EQ(error_of(text_with([](json& d) { d["states"][1]["name"] = "open\n"; })).location(), "states[1].name");
  const InputError key = error_of(text_with([](json& d) { d["states"][0]["poses"]["lid\x07"] = json::object(); }));
  EXPECT_EQ(key.location(), "states[0].poses.lid\x07");
  EXPECT_EQ(std::string(key.what()).find('\x07'), std::string::npos) << "printed raw";
}

TEST(HostileScene, AHugePrimitiveNamesTheFieldAtFault) {
  const InputError error = error_of(text_with([](json& d) { d["parts"][1] = {{"name", "post"}, {"cylinder", {{"radius", 1}, {"height", 1e300}}}}; }));
  EXPECT_EQ(error.location(), "parts[1].cylinder.height");
  EXPECT_NE(error.message().find("at most 1e+12"), std::string::npos) << error.what();
  EXPECT_EQ(error_of(text_with([](json& d) { d["parts"][0]["box"]["size"][1] = 1e300; })).location(),
            "parts[0].box.size[1]");
}

TEST(HostileScene, CoordinatesFarBeyondTheDesignAreRefused) {
  const InputError handle = error_of(text_with([](json& d) {
    d["transitions"][0]["tracks"]["lid"]["translation"][0]["out"] = {0, 1e20, 0};
  }));
  EXPECT_EQ(handle.location(), "transitions[0].tracks.lid.translation[0].out");
  EXPECT_NE(handle.message().find("1e+06 times the design's size"), std::string::npos) << handle.what();
  const InputError pose = error_of(text_with([](json& d) {
    d["states"][0]["poses"]["ball"] = {{"translation", {-1e300, 0, 0}}};
    d["states"][1]["poses"]["ball"] = {{"translation", {-1e300, 0, 0}}};
  }));
  EXPECT_EQ(pose.location(), "states[0].poses.ball.translation");
  // Within the range (the box reaches 0.5 from its center: up to 5e5) a far handle is fine.
  EXPECT_NO_THROW(parse_scene(text_with([](json& d) {
    d["transitions"][0]["tracks"]["lid"]["translation"][0]["out"] = {0, 4e5, 0};
  }), fs::current_path(), "far.json"));
}

/// A folder with a valid scene whose second part is the mesh at `mesh`, written as given.
fs::path scene_with_mesh(const std::string& mesh) {
  const fs::path dir = testing::fresh_temp_dir();
  json document = valid_scene();
  document["parts"][1] = {{"name", "ball"}, {"mesh", mesh}};
  std::ofstream(dir / "scene.json") << document.dump();
  return dir;
}

TEST(HostileScene, AFifoIsRefusedNotWaitedOn) {
  const fs::path dir = scene_with_mesh("pipe.obj");
  ASSERT_EQ(::mkfifo((dir / "pipe.obj").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((dir / "pipe.json").c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const InputError mesh = load_error(dir / "scene.json");
  EXPECT_EQ(mesh.location(), "parts[1].mesh");
  EXPECT_NE(mesh.message().find("is not a regular file (a FIFO)"), std::string::npos) << mesh.what();
  const InputError scene = load_error(dir / "pipe.json");
  EXPECT_EQ(scene.message(), "is not a regular file (a FIFO)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST(HostileScene, DeviceFilesAreRefusedNotReadForever) {
  const fs::path dir = scene_with_mesh("zero.stl");
  fs::create_symlink("/dev/zero", dir / "zero.stl");
  fs::create_symlink("/dev/urandom", dir / "random.json");
  EXPECT_NE(load_error(dir / "scene.json").message().find("through a symbolic link"), std::string::npos);
  const InputError mesh = load_error(dir / "scene.json", {.allow_outside_paths = true});
  EXPECT_EQ(mesh.location(), "parts[1].mesh");
  EXPECT_NE(mesh.message().find("is not a regular file (a character device)"), std::string::npos) << mesh.what();
  EXPECT_EQ(load_error(dir / "random.json").message(), "is not a regular file (a character device)");
}

TEST(HostileScene, AFileBeyondTheSizeLimitIsRefusedWithItsSize) {
  const fs::path dir = scene_with_mesh("huge.stl");
  std::ofstream(dir / "huge.stl").close();
  fs::resize_file(dir / "huge.stl", kMaxInputFileBytes + 1);  // sparse: no disk used
  const InputError error = load_error(dir / "scene.json");
  EXPECT_EQ(error.location(), "parts[1].mesh");
  EXPECT_NE(error.message().find("is 1073741825 bytes (1 GiB), more than the 1073741824 bytes (1 GiB) a loader reads"), std::string::npos) << error.what();
}

TEST(HostileScene, ASymlinkLoopIsNamedWithItsJsonPath) {
  const fs::path dir = scene_with_mesh("loop.obj");
  fs::create_symlink("loop.obj", dir / "loop.obj");
  const InputError error = load_error(dir / "scene.json");
  EXPECT_EQ(error.file(), (dir / "scene.json").string());
  EXPECT_EQ(error.location(), "parts[1].mesh");
  EXPECT_NE(error.message().find("symbolic links"), std::string::npos) << error.what();
}

TEST(HostileScene, MeshPathsMustStayInTheScenesFolder) {
  const fs::path outside = testing::fresh_temp_dir();
  geometry::save_obj(outside / "secret.obj", geometry::make_box({1, 1, 1}));
  const fs::path dir = outside / "design";
  fs::create_directories(dir / "meshes");
  fs::create_symlink(outside / "secret.obj", dir / "meshes" / "link.obj");
  const auto write_scene = [&](const std::string& mesh) {
    json document = valid_scene();
    document["parts"][1] = {{"name", "ball"}, {"mesh", mesh}};
    std::ofstream(dir / "scene.json") << document.dump();
  };
  for (const auto& [mesh, why] : {std::pair{(outside / "secret.obj").string(), "is an absolute path"},
                                  std::pair{std::string("../secret.obj"), "leads out of the file's folder with \"..\""},
                                  std::pair{std::string("meshes/../../secret.obj"), "with \"..\""},
                                  std::pair{std::string("meshes/link.obj"), "through a symbolic link"}}) {
    write_scene(mesh);
    const InputError error = load_error(dir / "scene.json");
    EXPECT_EQ(error.location(), "parts[1].mesh") << mesh;
    EXPECT_NE(error.message().find(why), std::string::npos) << error.what();
    EXPECT_NE(error.message().find("--allow-outside-paths"), std::string::npos) << error.what();
    EXPECT_NO_THROW(load_scene(dir / "scene.json", {.allow_outside_paths = true})) << mesh;
  }
  write_scene("meshes/../meshes/./inside.obj");
  geometry::save_obj(dir / "meshes" / "inside.obj", geometry::make_box({1, 1, 1}));
  EXPECT_NO_THROW(load_scene(dir / "scene.json"));
}

/// Mesh paths made of hostile pieces — FIFOs, devices, loops, links out, `..`, absolute and
/// percent-encoded paths — never hang, never crash, and never load a mesh from outside the
/// design unless allowed. RECONFIG_FUZZ_TRIALS and RECONFIG_FUZZ_SEED set the campaign.
TEST(HostileScene, FuzzedMeshPathsNeverHangOrLeaveTheDesign) {
  const fs::path root = testing::fresh_temp_dir();
  const fs::path dir = root / "design";
  fs::create_directories(dir / "sub");
  geometry::save_obj(dir / "sub" / "inside.obj", geometry::make_box({1, 1, 1}));
  geometry::save_obj(root / "outside.obj", geometry::make_box({2, 2, 2}));
  ASSERT_EQ(::mkfifo((dir / "fifo.obj").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.stl");
  fs::create_symlink("/dev/urandom", dir / "sub" / "random.glb");
  fs::create_symlink("loop.obj", dir / "loop.obj");
  fs::create_symlink("..", dir / "sub" / "up");
  fs::create_symlink(root / "outside.obj", dir / "out.obj");
  const std::vector<std::string> pieces = {"..", ".", "sub", "up", "inside.obj", "outside.obj", "fifo.obj", "zero.stl",
                                           "random.glb", "loop.obj", "out.obj", "%2e%2e", "", "design", "/dev/zero",
                                           root.string(), "missing.obj", "sub/inside.obj", "sub/up/outside.obj",
                                           "../outside.obj", "sub/../sub/inside.obj"};
  std::mt19937 rng(static_cast<unsigned>(testing::fuzz_setting("RECONFIG_FUZZ_SEED", 25)));
  const int trials = testing::fuzz_setting("RECONFIG_FUZZ_TRIALS", 400);
  int loaded = 0, loaded_outside = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int trial = 0; trial < trials; ++trial) {
    std::string mesh;
    for (int k = 0, n = 1 + static_cast<int>(rng() % 3); k < n; ++k) mesh += (k ? "/" : "") + pieces[rng() % pieces.size()];
    json document = valid_scene();
    document["parts"][1] = {{"name", "ball"}, {"mesh", mesh}};
    const bool allowed = rng() % 4 == 0;
    try {
      const Reconfigurable scene = parse_scene(document.dump(), dir, "fuzz.json", {.allow_outside_paths = allowed});
      ++loaded;
      const bool outside = scene.parts[1].mesh.V.cwiseAbs().maxCoeff() > 0.75;  // the 2×2×2 box
      loaded_outside += outside;
      EXPECT_TRUE(allowed || !outside) << "read a mesh outside the design through \"" << mesh << "\"";
    } catch (const InputError& error) {
      EXPECT_LT(std::string(error.what()).size(), 3 * kMaxInputErrorPart);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ fuzz     ] %d hostile mesh paths in %.2f s: %d loaded, %d of them from outside (allowed)\n", trials,
              seconds, loaded, loaded_outside);
  EXPECT_GT(loaded, 0);
}

}  // namespace
}  // namespace reconfig::scene
