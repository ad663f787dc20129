#include "geometry/detail/read_off.h"
#include "geometry/detail/split_tokens.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include "geometry/detail/triangulate_polygon.h"
#include "reconfig/common/input_error.h"

namespace reconfig::geometry::detail {
namespace {

/// The significant lines of the text (comments stripped, blank lines skipped), one at a time.
class Lines {
 public:
  explicit Lines(const std::string& text) : text_(text) {}

  /// Next non-blank line, its tokens in `tokens`; false at the end.
  bool next(std::vector<std::string_view>& tokens) {
    while (position_ < text_.size()) {
      std::size_t end = text_.find('\n', position_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(position_, end - position_);
      position_ = end + 1;
      ++number_;
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      tokens.clear();
      split_tokens(line, std::string_view(" \t\r\v\f\0", 6), tokens);
      if (!tokens.empty()) return true;
    }
    return false;
  }

  std::string where() const { return "line " + std::to_string(number_); }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  long long number_ = 0;
};

bool parse(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size();
}

bool parse(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size();
}

bool ends_with_off(std::string_view token) {
  return token.size() >= 3 && token.substr(token.size() - 3) == "OFF";
}

}  // namespace

RawMesh read_off(const std::string& bytes) {
  Lines lines(bytes);
  std::vector<std::string_view> tokens;
  if (!lines.next(tokens)) throw InputError("", "", "empty OFF file");

  std::size_t first_count = 0;  // index in `tokens` of the vertex count
  if (ends_with_off(tokens[0])) {
    const std::string_view prefix = tokens[0].substr(0, tokens[0].size() - 3);
    if (prefix.find_first_not_of("STCN") != std::string_view::npos)
      throw InputError("", lines.where(), "unsupported OFF variant " + std::string(tokens[0]) + " (only 3D OFF)");
    if (tokens.size() > 1 && tokens[1] == "BINARY")
      throw InputError("", lines.where(), "binary OFF is not supported");
    first_count = 1;
    if (tokens.size() == 1) {  // the counts are on the next line
      if (!lines.next(tokens)) throw InputError("", lines.where(), "missing vertex and face counts");
      first_count = 0;
    }
  }
  long long vertex_count = -1, face_count = -1;
  if (tokens.size() < first_count + 2 || !parse(tokens[first_count], vertex_count) ||
      !parse(tokens[first_count + 1], face_count) || vertex_count < 0 || face_count < 0 ||
      vertex_count > 0x7fffffff || face_count > 0x7fffffff)
    throw InputError("", lines.where(), "expected the vertex and face counts");

  RawMesh content;
  // Never trust the header for the allocation: each vertex needs at least 6 bytes.
  content.positions.reserve(static_cast<std::size_t>(std::min<long long>(vertex_count, static_cast<long long>(bytes.size() / 6))));
  for (long long v = 0; v < vertex_count; ++v) {
    if (!lines.next(tokens))
      throw InputError("", lines.where(), "file ends after " + std::to_string(v) + " of " +
                                              std::to_string(vertex_count) + " vertices");
    Eigen::Vector3d p;
    if (tokens.size() < 3 || !parse(tokens[0], p.x()) || !parse(tokens[1], p.y()) || !parse(tokens[2], p.z()))
      throw InputError("", lines.where() + ", vertex " + std::to_string(v), "expected three coordinates");
    if (!p.allFinite())
      throw InputError("", lines.where() + ", vertex " + std::to_string(v), "coordinate is NaN or infinite");
    content.positions.push_back(p);
  }
  std::vector<int> loop;
  for (long long f = 0; f < face_count; ++f) {
    if (!lines.next(tokens))
      throw InputError("", lines.where(), "file ends after " + std::to_string(f) + " of " +
                                              std::to_string(face_count) + " faces");
    const std::string where = lines.where() + ", face " + std::to_string(f);
    long long corners = 0;
    if (!parse(tokens[0], corners) || corners < 0) throw InputError("", where, "expected the number of corners");
    if (static_cast<long long>(tokens.size()) - 1 < corners)
      throw InputError("", where, "expected " + std::to_string(corners) + " vertex indices");
    loop.clear();
    for (long long k = 1; k <= corners; ++k) {
      long long index = -1;
      if (!parse(tokens[static_cast<std::size_t>(k)], index))
        throw InputError("", where, "vertex index '" + std::string(tokens[static_cast<std::size_t>(k)]) + "' is not an integer");
      if (index < 0 || index >= vertex_count)
        throw InputError("", where, "vertex index " + std::to_string(index) + " out of range (" +
                                        std::to_string(vertex_count) + " vertices)");
      loop.push_back(static_cast<int>(index));
    }
    if (corners >= 3) triangulate_polygon(content.positions, loop, content.triangles);
  }
  return content;
}

}  // namespace reconfig::geometry::detail
