#include "reconfig/geometry/save_mesh.h"

#include <Eigen/Geometry>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "reconfig/common/input_error.h"
#include "reconfig/common/write_atomically.h"

namespace reconfig::geometry {
namespace {

namespace fs = std::filesystem;

/// Refuses to write what `load_mesh` would refuse to read.
void check_writable(const fs::path& path, const Mesh& mesh) {
  for (int v = 0; v < mesh.vertex_count(); ++v)
    if (!mesh.V.row(v).allFinite())
      throw InputError(path.string(), "vertex " + std::to_string(v), "coordinate is NaN or infinite");
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.F(f, k) < 0 || mesh.F(f, k) >= mesh.vertex_count())
        throw InputError(path.string(), "face " + std::to_string(f), "vertex index out of range");
}

Eigen::Vector3d unit_normal(const Mesh& mesh, int f) {
  const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0 && std::isfinite(length) ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

void put_float(std::ostream& out, double value) {
  const float f = static_cast<float>(value);
  std::array<unsigned char, 4> bytes;
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  for (int i = 0; i < 4; ++i) bytes[static_cast<std::size_t>(i)] = static_cast<unsigned char>(bits >> (8 * i));
  out.write(reinterpret_cast<const char*>(bytes.data()), 4);
}

std::string format_double(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string format_float(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(static_cast<float>(value)));
  return buffer;
}

/// `v` and `f` lines of `mesh`, its vertices numbered after the `first_vertex` written before.
void write_obj_lines(std::ostream& out, const Mesh& mesh, int first_vertex) {
  for (int v = 0; v < mesh.vertex_count(); ++v)
    out << "v " << format_double(mesh.V(v, 0)) << ' ' << format_double(mesh.V(v, 1)) << ' '
        << format_double(mesh.V(v, 2)) << '\n';
  const int base = first_vertex + 1;  // OBJ counts from 1
  for (int f = 0; f < mesh.face_count(); ++f)
    out << "f " << mesh.F(f, 0) + base << ' ' << mesh.F(f, 1) + base << ' ' << mesh.F(f, 2) + base << '\n';
}

/// An OBJ object name: one word of printable characters (the name runs to the end of the line).
std::string obj_name(const std::string& name) {
  std::string word = name.empty() ? "unnamed" : name;
  for (char& c : word)
    if (static_cast<unsigned char>(c) <= ' ' || c == 0x7f) c = '_';
  return word;
}

}  // namespace

void save_obj(const fs::path& path, const Mesh& mesh) {
  check_writable(path, mesh);
  write_atomically(path, [&](std::ostream& out) {
    out << "# " << mesh.vertex_count() << " vertices, " << mesh.face_count() << " triangles\n";
    write_obj_lines(out, mesh, 0);
  });
}

void save_obj(const fs::path& path, const std::vector<ObjObject>& objects) {
  int vertices = 0, faces = 0;
  for (const ObjObject& object : objects) {
    check_writable(path, object.mesh);
    vertices += object.mesh.vertex_count();
    faces += object.mesh.face_count();
  }
  write_atomically(path, [&](std::ostream& out) {
    out << "# " << objects.size() << " objects, " << vertices << " vertices, " << faces << " triangles\n";
    int written = 0;
    for (const ObjObject& object : objects) {
      out << "o " << obj_name(object.name) << '\n';
      write_obj_lines(out, object.mesh, written);
      written += object.mesh.vertex_count();
    }
  });
}

void save_stl(const fs::path& path, const Mesh& mesh, bool binary) {
  check_writable(path, mesh);
  write_atomically(path, [&](std::ostream& out) {
    if (binary) {
      std::array<char, 80> header{};
      const char title[] = "binary STL written by reconfig";
      std::memcpy(header.data(), title, sizeof title - 1);
      out.write(header.data(), header.size());
      const auto count = static_cast<std::uint32_t>(mesh.face_count());
      for (int i = 0; i < 4; ++i) out.put(static_cast<char>((count >> (8 * i)) & 0xff));
      for (int f = 0; f < mesh.face_count(); ++f) {
        const Eigen::Vector3d n = unit_normal(mesh, f);
        for (int k = 0; k < 3; ++k) put_float(out, n[k]);
        for (int c = 0; c < 3; ++c)
          for (int k = 0; k < 3; ++k) put_float(out, mesh.V(mesh.F(f, c), k));
        out.put(0);
        out.put(0);
      }
    } else {
      out << "solid reconfig\n";
      for (int f = 0; f < mesh.face_count(); ++f) {
        const Eigen::Vector3d n = unit_normal(mesh, f);
        out << "  facet normal " << format_float(n.x()) << ' ' << format_float(n.y()) << ' ' << format_float(n.z())
            << "\n    outer loop\n";
        for (int c = 0; c < 3; ++c) {
          const int v = mesh.F(f, c);
          out << "      vertex " << format_float(mesh.V(v, 0)) << ' ' << format_float(mesh.V(v, 1)) << ' '
              << format_float(mesh.V(v, 2)) << '\n';
        }
        out << "    endloop\n  endfacet\n";
      }
      out << "endsolid reconfig\n";
    }
  });
}

}  // namespace reconfig::geometry
