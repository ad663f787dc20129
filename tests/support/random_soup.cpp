#include "support/random_soup.h"

#include <cmath>

namespace reconfig::testing {

geometry::Mesh random_soup(std::mt19937& rng, int count, const RandomSoupOptions& options) {
  std::uniform_real_distribution<double> center_coordinate(options.lo, options.hi), unit(-1, 1),
      size(options.min_size, options.max_size);
  const auto snapped = [&](double x) { return options.grid > 0 ? std::round(x / options.grid) * options.grid : x; };
  geometry::Mesh mesh;
  mesh.V.resize(3 * count, 3);
  mesh.F.resize(count, 3);
  for (int f = 0; f < count; ++f) {
    const Eigen::RowVector3d center(center_coordinate(rng), center_coordinate(rng), center_coordinate(rng));
    const double s = options.min_size < options.max_size ? size(rng) : options.min_size;
    for (int c = 0; c < 3; ++c) {
      const Eigen::RowVector3d p = center + s * Eigen::RowVector3d(unit(rng), unit(rng), unit(rng));
      mesh.V.row(3 * f + c) = p.unaryExpr(snapped);
      mesh.F(f, c) = 3 * f + c;
    }
  }
  return mesh;
}

}  // namespace reconfig::testing
