#pragma once
/// @file
/// The `PartShape`s of one design's parts, built once each.

#include <map>
#include <memory>

#include "reconfig/resolve/part_shape.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::resolve {

/// Shapes by part index for designs that share their parts' geometry (edits of keys keep it;
/// use a new cache after a part's mesh changes). Not thread-safe: look up the shapes a
/// parallel computation needs before it starts.
class ShapeCache {
 public:
  /// The shape of part `part` of `scene`, built on first use.
  const PartShape& shape(const scene::Reconfigurable& scene, int part);

 private:
  std::map<int, std::unique_ptr<PartShape>> shapes_;
};

}  // namespace reconfig::resolve
