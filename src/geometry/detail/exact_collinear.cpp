#include "geometry/detail/exact_collinear.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace reconfig::geometry::detail {

bool exactly_collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  return CGAL::collinear(Point(a.x(), a.y(), a.z()), Point(b.x(), b.y(), b.z()), Point(c.x(), c.y(), c.z()));
}

}  // namespace reconfig::geometry::detail
