#include "support/test_data.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <unistd.h>

namespace fs = std::filesystem;

namespace reconfig::testing {

fs::path source_dir() { return RECONFIG_SOURCE_DIR; }
fs::path binary_dir() { return RECONFIG_BINARY_DIR; }

fs::path cgal_mesh(const std::string& name) {
  const fs::path archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  const fs::path root = binary_dir() / "test-data" / "cgal";
  const fs::path mesh = root / "data" / "meshes" / name;
  if (fs::exists(mesh)) return mesh;
  if (!fs::exists(archive))
    throw std::runtime_error("CGAL demo data missing (" + archive.string() + "): run ./run deps");
  // Test processes run in parallel: extract into a private folder, then rename it into place.
  const fs::path staging = binary_dir() / "test-data" / ("cgal.tmp." + std::to_string(::getpid()));
  fs::create_directories(staging);
  const std::string command = "tar xzf " + archive.string() + " -C " + staging.string() + " data/meshes";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("could not extract " + archive.string());
  std::error_code ignored;
  fs::rename(staging, root, ignored);  // loses the race harmlessly if another process won
  fs::remove_all(staging, ignored);
  if (!fs::exists(mesh)) throw std::runtime_error("no mesh " + name + " in " + archive.string());
  return mesh;
}

fs::path fresh_temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "anonymous";
  for (char& c : name)
    if (c == '/') c = '_';
  const fs::path dir = binary_dir() / "test-tmp" / (name + "." + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace reconfig::testing
