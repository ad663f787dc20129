#include "geometry/detail/read_ply.h"
#include "geometry/detail/split_tokens.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

#include "geometry/detail/triangulate_polygon.h"
#include "reconfig/common/input_error.h"

namespace reconfig::geometry::detail {
namespace {

enum class Format { kAscii, kLittle, kBig };
enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

std::optional<Type> type_named(std::string_view name) {
  if (name == "char" || name == "int8") return Type::kInt8;
  if (name == "uchar" || name == "uint8") return Type::kUint8;
  if (name == "short" || name == "int16") return Type::kInt16;
  if (name == "ushort" || name == "uint16") return Type::kUint16;
  if (name == "int" || name == "int32") return Type::kInt32;
  if (name == "uint" || name == "uint32") return Type::kUint32;
  if (name == "float" || name == "float32") return Type::kFloat32;
  if (name == "double" || name == "float64") return Type::kFloat64;
  return std::nullopt;
}

std::size_t size_of(Type t) {
  switch (t) {
    case Type::kInt8: case Type::kUint8: return 1;
    case Type::kInt16: case Type::kUint16: return 2;
    case Type::kInt32: case Type::kUint32: case Type::kFloat32: return 4;
    case Type::kFloat64: return 8;
  }
  return 1;
}

bool is_integer(Type t) { return t != Type::kFloat32 && t != Type::kFloat64; }

struct Property {
  std::string name;
  Type type = Type::kFloat32;
  bool is_list = false;
  Type count_type = Type::kUint8;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  split_tokens(line, std::string_view(" \t\r"), tokens);
  return tokens;
}

/// Reads scalars from the data section, ascii or binary, never past its end.
class Reader {
 public:
  Reader(std::string_view data, Format format) : data_(data), format_(format) {}

  /// Next value of type `t`; false at the end of the data or on a malformed token.
  bool read(Type t, double& value) {
    if (format_ == Format::kAscii) return read_token(t, value);
    const std::size_t n = size_of(t);
    if (data_.size() - position_ < n) return false;
    unsigned char b[8];
    std::memcpy(b, data_.data() + position_, n);
    position_ += n;
    if ((format_ == Format::kBig) == (std::endian::native == std::endian::little))
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (t) {
      case Type::kInt8: value = static_cast<std::int8_t>(b[0]); break;
      case Type::kUint8: value = b[0]; break;
      case Type::kInt16: { std::int16_t x; std::memcpy(&x, b, 2); value = x; break; }
      case Type::kUint16: { std::uint16_t x; std::memcpy(&x, b, 2); value = x; break; }
      case Type::kInt32: { std::int32_t x; std::memcpy(&x, b, 4); value = x; break; }
      case Type::kUint32: { std::uint32_t x; std::memcpy(&x, b, 4); value = x; break; }
      case Type::kFloat32: { float x; std::memcpy(&x, b, 4); value = x; break; }
      case Type::kFloat64: { double x; std::memcpy(&x, b, 8); value = x; break; }
    }
    return true;
  }

  /// Bytes (binary) or characters (ascii) left: a bound on how many values can still come.
  std::size_t remaining() const { return data_.size() - position_; }

 private:
  bool read_token(Type t, double& value) {
    auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; };
    while (position_ < data_.size() && is_space(data_[position_])) ++position_;
    std::size_t end = position_;
    while (end < data_.size() && !is_space(data_[end]) && data_[end] != '\0') ++end;
    if (end == position_) return false;  // end of data, or a NUL byte
    std::string_view token = data_.substr(position_, end - position_);
    position_ = end;
    if (token.front() == '+') token.remove_prefix(1);
    if (is_integer(t)) {
      long long x = 0;
      const auto [p, error] = std::from_chars(token.data(), token.data() + token.size(), x);
      value = static_cast<double>(x);
      return error == std::errc() && p == token.data() + token.size();
    }
    const auto [p, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    return error == std::errc() && p == token.data() + token.size();
  }

  std::string_view data_;
  Format format_;
  std::size_t position_ = 0;
};

}  // namespace

RawMesh read_ply(const std::string& bytes) {
  const std::string_view text(bytes);
  // --- header ---
  std::size_t position = 0;
  int line_number = 0;
  auto next_line = [&](std::string_view& line) {
    if (position >= text.size()) return false;
    std::size_t end = text.find('\n', position);
    if (end == std::string_view::npos) end = text.size();
    line = text.substr(position, end - position);
    position = std::min(text.size(), end + 1);
    ++line_number;
    return true;
  };
  auto where = [&] { return "header line " + std::to_string(line_number); };
  std::string_view line;
  if (!next_line(line) || split(line) != std::vector<std::string_view>{"ply"})
    throw InputError("", "", "not a PLY file (no 'ply' line)");
  std::optional<Format> format;
  std::vector<Element> elements;
  bool ended = false;
  while (!ended && next_line(line)) {
    const std::vector<std::string_view> t = split(line);
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "format") {
      if (t.size() < 2) throw InputError("", where(), "incomplete format line");
      if (t[1] == "ascii") format = Format::kAscii;
      else if (t[1] == "binary_little_endian") format = Format::kLittle;
      else if (t[1] == "binary_big_endian") format = Format::kBig;
      else throw InputError("", where(), "unknown PLY format '" + std::string(t[1]) + "'");
    } else if (t[0] == "element") {
      long long count = -1;
      if (t.size() != 3 || std::from_chars(t[2].data(), t[2].data() + t[2].size(), count).ec != std::errc() ||
          count < 0 || count > 0x7fffffff)
        throw InputError("", where(), "expected 'element <name> <count>'");
      elements.push_back({std::string(t[1]), count, {}});
    } else if (t[0] == "property") {
      if (elements.empty()) throw InputError("", where(), "property before any element");
      Property p;
      if (t.size() == 5 && t[1] == "list") {
        const auto count_type = type_named(t[2]), item_type = type_named(t[3]);
        if (!count_type || !item_type || !is_integer(*count_type))
          throw InputError("", where(), "bad list property types");
        p = {std::string(t[4]), *item_type, true, *count_type};
      } else if (t.size() == 3 && type_named(t[1])) {
        p = {std::string(t[2]), *type_named(t[1]), false, Type::kUint8};
      } else {
        throw InputError("", where(), "expected 'property <type> <name>' or 'property list <type> <type> <name>'");
      }
      elements.back().properties.push_back(p);
    } else if (t[0] == "end_header") {
      ended = true;
    } else {
      throw InputError("", where(), "unexpected header line '" + std::string(line.substr(0, 40)) + "'");
    }
  }
  if (!ended) throw InputError("", where(), "header does not end with 'end_header'");
  if (!format) throw InputError("", "", "PLY header has no format line");

  // --- data ---
  Reader reader(text.substr(position), *format);
  RawMesh mesh;
  long long vertex_count = 0;
  bool vertices_read = false;
  std::vector<double> values;
  std::vector<int> loop;
  for (const Element& element : elements) {
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    int x = -1, y = -1, z = -1, indices = -1;
    for (int i = 0; i < static_cast<int>(element.properties.size()); ++i) {
      const Property& p = element.properties[static_cast<std::size_t>(i)];
      if (!p.is_list && p.name == "x") x = i;
      if (!p.is_list && p.name == "y") y = i;
      if (!p.is_list && p.name == "z") z = i;
      if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) indices = i;
    }
    if (is_vertex && (x < 0 || y < 0 || z < 0)) throw InputError("", "", "vertex element without x, y, z");
    if (is_face && indices < 0) throw InputError("", "", "face element without a vertex_indices list");
    if (is_face && !vertices_read) throw InputError("", "", "face element before the vertex element");
    if (element.properties.empty()) continue;
    if (is_vertex)
      mesh.positions.reserve(std::min<std::size_t>(static_cast<std::size_t>(element.count), reader.remaining()));
    for (long long r = 0; r < element.count; ++r) {
      const std::string here = element.name + " " + std::to_string(r);
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      loop.clear();
      for (int i = 0; i < static_cast<int>(element.properties.size()); ++i) {
        const Property& property = element.properties[static_cast<std::size_t>(i)];
        double value = 0;
        if (!property.is_list) {
          if (!reader.read(property.type, value)) throw InputError("", here, "missing or malformed value");
          if (i == x) p.x() = value;
          if (i == y) p.y() = value;
          if (i == z) p.z() = value;
          continue;
        }
        double count = 0;
        if (!reader.read(property.count_type, count) || count < 0 || count > static_cast<double>(reader.remaining()))
          throw InputError("", here, "missing or malformed list length");
        for (long long k = 0; k < static_cast<long long>(count); ++k) {
          if (!reader.read(property.type, value)) throw InputError("", here, "missing or malformed list value");
          if (i != indices) continue;
          if (!is_integer(property.type) && value != std::floor(value))
            throw InputError("", here, "vertex index is not an integer");
          if (!(value >= 0 && value < static_cast<double>(vertex_count)))
            throw InputError("", here, "vertex index " + std::to_string(static_cast<long long>(value)) +
                                           " out of range (" + std::to_string(vertex_count) + " vertices)");
          loop.push_back(static_cast<int>(value));
        }
      }
      if (is_vertex) {
        if (!p.allFinite()) throw InputError("", here, "coordinate is NaN or infinite");
        mesh.positions.push_back(p);
      } else if (is_face && loop.size() >= 3) {
        triangulate_polygon(mesh.positions, loop, mesh.triangles);
      }
    }
    if (is_vertex) {
      vertex_count = element.count;
      vertices_read = true;
    }
  }
  return mesh;
}

}  // namespace reconfig::geometry::detail
