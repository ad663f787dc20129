# Every dependency comes from a Debian 12 package (see `run deps`).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(fmt REQUIRED)
find_package(assimp REQUIRED)
find_package(CGAL REQUIRED)
# OpenVDB 10 (libopenvdb-dev) ships only a find module, which wants Boost components the
# shared library does not need: the imported target is made here from the header and library.
find_path(OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
find_library(OPENVDB_LIBRARY openvdb REQUIRED)
find_library(IMATH_LIBRARY Imath REQUIRED)  # libimath-dev, a dependency of libopenvdb-dev (half floats)
add_library(OpenVDB::openvdb UNKNOWN IMPORTED)
set_target_properties(OpenVDB::openvdb PROPERTIES IMPORTED_LOCATION ${OPENVDB_LIBRARY})
target_include_directories(OpenVDB::openvdb SYSTEM INTERFACE ${OPENVDB_INCLUDE_DIR})
target_link_libraries(OpenVDB::openvdb INTERFACE TBB::tbb ${IMATH_LIBRARY})
find_package(Threads REQUIRED)
if(RECONFIG_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(RECONFIG_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
# The renderer: OpenGL through libepoxy (EGL surfaceless context for headless use), PNG via stb.
find_package(PkgConfig REQUIRED)
pkg_check_modules(epoxy REQUIRED IMPORTED_TARGET epoxy)
pkg_check_modules(stb REQUIRED IMPORTED_TARGET stb)
# The studio: a GLFW window and Dear ImGui 1.86 (libimgui-dev ships no CMake or pkg-config
# target for its backends: they are inside libimgui.a).
find_package(glfw3 3.3 REQUIRED)
pkg_check_modules(imgui REQUIRED IMPORTED_TARGET imgui)
