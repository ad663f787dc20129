#pragma once
// A track's `"ease"` (docs/file-formats.md): the handles of translation keys written without
// `in` or `out`. "smooth" (the default) puts them on the key's point, so each segment starts
// and ends at rest; "linear" puts them at the thirds of the chord to the neighbouring key, so
// the part moves at constant speed along the straight line between keys.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "reconfig/motion/bezier_translation_track.h"
#include "scene/detail/json_cursor.h"

namespace reconfig::scene::detail {

enum class Ease { smooth, linear };

/// A translation key as written in the file: its handles may be left out.
struct WrittenTranslationKey {
  double time = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> in, out;
};

/// `"smooth"` or `"linear"` (error naming `c` otherwise).
Ease read_ease(const JsonCursor& c);

/// The keys with every missing handle filled in as `ease` says; written handles are kept.
std::vector<motion::TranslationKey> ease_translation_keys(const std::vector<WrittenTranslationKey>& keys, Ease ease);

}  // namespace reconfig::scene::detail
