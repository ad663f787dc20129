#pragma once
/// @file
/// A count with its noun, as the studio's labels say it: "1 transition", "2 transitions",
/// "0 collision intervals".

#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace reconfig::studio {

/// `count` and `noun`, the noun plural (an added "s") unless the count is 1.
inline std::string counted(std::size_t count, std::string_view noun) {
  return fmt::format("{} {}{}", count, noun, count == 1 ? "" : "s");
}

}  // namespace reconfig::studio
