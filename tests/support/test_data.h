#pragma once
/// @file
/// Paths the tests need: the source tree, the CGAL demo meshes, fresh temporary folders.

#include <filesystem>
#include <string>

namespace reconfig::testing {

/// The repository root (examples/, tests/data/ live there).
std::filesystem::path source_dir();

/// The build folder (build/bin/reconfig lives under it).
std::filesystem::path binary_dir();

/// `data/meshes/<name>` from the CGAL demo data (Debian package `libcgal-demo`), extracted
/// once into the build folder. Fails the calling test (via an exception) if the package is
/// missing: `./run deps` installs it.
std::filesystem::path cgal_mesh(const std::string& name);

/// A new empty folder under the build folder, unique to the running test.
std::filesystem::path fresh_temp_dir();

}  // namespace reconfig::testing
