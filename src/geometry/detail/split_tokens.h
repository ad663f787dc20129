#pragma once
// Splitting a text line of a mesh file into tokens.

#include <string_view>
#include <vector>

namespace reconfig::geometry::detail {

/// Appends to `tokens` the maximal runs of `line` that contain none of the `separators`.
inline void split_tokens(std::string_view line, std::string_view separators, std::vector<std::string_view>& tokens) {
  std::size_t i = 0;
  while (i < line.size()) {
    i = line.find_first_not_of(separators, i);
    if (i == std::string_view::npos) return;
    std::size_t j = line.find_first_of(separators, i);
    if (j == std::string_view::npos) j = line.size();
    tokens.push_back(line.substr(i, j - i));
    i = j;
  }
}

}  // namespace reconfig::geometry::detail
