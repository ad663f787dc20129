#include "scene/detail/translation_ease.h"

#include <fmt/format.h>

#include <string>

namespace reconfig::scene::detail {

Ease read_ease(const JsonCursor& c) {
  const std::string ease = c.as_string();
  if (ease == "smooth") return Ease::smooth;
  if (ease == "linear") return Ease::linear;
  c.fail(fmt::format("unknown ease \"{}\" (expected \"smooth\" or \"linear\")", ease));
}

std::vector<motion::TranslationKey> ease_translation_keys(const std::vector<WrittenTranslationKey>& keys, Ease ease) {
  std::vector<motion::TranslationKey> result;
  result.reserve(keys.size());
  for (std::size_t j = 0; j < keys.size(); ++j) {
    const Eigen::Vector3d& point = keys[j].point;
    // Linear: a third of the way to the neighbour; the ends (no neighbour) keep the point.
    const auto third_toward = [&](bool exists, std::size_t neighbour) -> Eigen::Vector3d {
      if (ease == Ease::smooth || !exists) return point;
      return point + (keys[neighbour].point - point) / 3;
    };
    result.push_back({keys[j].time, point, keys[j].in.value_or(third_toward(j > 0, j - 1)),
                      keys[j].out.value_or(third_toward(j + 1 < keys.size(), j + 1))});
  }
  return result;
}

}  // namespace reconfig::scene::detail
