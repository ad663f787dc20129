#pragma once
/// @file
/// Random triangle soups for oracle tests of trees and bounds: independent triangles scattered
/// in a box, from slivers to a sizeable fraction of it.

#include <random>

#include "reconfig/geometry/mesh.h"

namespace reconfig::testing {

struct RandomSoupOptions {
  double lo = 0, hi = 1;                      ///< triangle centers are drawn in [lo, hi]³
  double min_size = 0.1, max_size = 0.1;      ///< corners lie within size·[−1, 1]³ of the center
  double grid = 0;                            ///< if > 0, coordinates snap to multiples of it (exact ties)
};

/// `count` triangles, each with its own three vertices.
geometry::Mesh random_soup(std::mt19937& rng, int count, const RandomSoupOptions& options = {});

}  // namespace reconfig::testing
