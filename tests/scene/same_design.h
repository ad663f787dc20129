#pragma once
// Whether two designs are the same: the same JSON (names, sources, poses, keys) and the same
// rest meshes, part by part.

#include <gtest/gtest.h>

#include "reconfig/scene/reconfigurable.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::scene {

inline ::testing::AssertionResult same_design(const Reconfigurable& a, const Reconfigurable& b) {
  const std::string ja = scene_to_json(a, "/"), jb = scene_to_json(b, "/");
  if (ja != jb) return ::testing::AssertionFailure() << "the JSON differs:\n" << ja << "\n---\n" << jb;
  for (std::size_t p = 0; p < a.parts.size(); ++p)
    if (a.parts[p].mesh.V != b.parts[p].mesh.V || a.parts[p].mesh.F != b.parts[p].mesh.F ||
        a.parts[p].center != b.parts[p].center)
      return ::testing::AssertionFailure() << "part " << p << " has another mesh or pivot";
  return ::testing::AssertionSuccess();
}

}  // namespace reconfig::scene
