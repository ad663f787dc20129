#include "geometry/detail/read_obj.h"
#include "geometry/detail/split_tokens.h"

#include <charconv>
#include <string_view>
#include <vector>

#include "geometry/detail/triangulate_polygon.h"
#include "reconfig/common/input_error.h"

namespace reconfig::geometry::detail {
namespace {

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  split_tokens(line, std::string_view(" \t\r\v\f"), tokens);
  return tokens;
}

template <class T>
bool parse(std::string_view token, T& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size();
}

}  // namespace

RawMesh read_obj(const std::string& bytes) {
  RawMesh mesh;
  const std::string_view text(bytes);
  std::size_t position = 0;
  long long line_number = 0;
  std::string joined;  // a logical line made of continued physical lines
  std::vector<int> loop;
  while (position < text.size()) {
    const long long first_line = line_number + 1;
    joined.clear();
    for (;;) {  // gather one logical line
      std::size_t end = text.find('\n', position);
      if (end == std::string_view::npos) end = text.size();
      std::string_view physical = text.substr(position, end - position);
      position = end + 1;
      ++line_number;
      while (!physical.empty() && physical.back() == '\r') physical.remove_suffix(1);
      if (!physical.empty() && physical.back() == '\\' && position < text.size()) {
        joined.append(physical.substr(0, physical.size() - 1));
        joined.push_back(' ');
        continue;
      }
      joined.append(physical);
      break;
    }
    std::string_view line = joined;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    const std::vector<std::string_view> tokens = split(line);
    if (tokens.empty()) continue;
    const std::string where = "line " + std::to_string(first_line);
    if (tokens[0] == "v") {
      Eigen::Vector3d p;
      if (tokens.size() < 4 || !parse(tokens[1], p.x()) || !parse(tokens[2], p.y()) || !parse(tokens[3], p.z()))
        throw InputError("", where, "expected 'v x y z'");
      if (!p.allFinite())
        throw InputError("", where + ", vertex " + std::to_string(mesh.positions.size() + 1),
                         "coordinate is NaN or infinite");
      mesh.positions.push_back(p);
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) throw InputError("", where, "a face needs at least three corners");
      loop.clear();
      const auto count = static_cast<long long>(mesh.positions.size());
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view corner = tokens[k].substr(0, tokens[k].find('/'));
        long long index = 0;
        if (!parse(corner, index)) throw InputError("", where, "bad face corner '" + std::string(tokens[k]) + "'");
        const long long resolved = index < 0 ? count + index : index - 1;  // negative: relative to the end
        if (index == 0 || resolved < 0 || resolved >= count)
          throw InputError("", where, "vertex index " + std::to_string(index) + " out of range (" +
                                          std::to_string(count) + " vertices so far)");
        loop.push_back(static_cast<int>(resolved));
      }
      triangulate_polygon(mesh.positions, loop, mesh.triangles);
    }
  }
  return mesh;
}

}  // namespace reconfig::geometry::detail
