#include "reconfig/geometry/display_simplification.h"

#include <gtest/gtest.h>

#include "reconfig/geometry/load_mesh.h"
#include "support/test_data.h"

namespace reconfig::geometry {
namespace {

/// Largest distance from a point of `a` to the nearest point of `b` (vertex sets, brute force).
double one_sided_distance(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b) {
  double worst = 0;
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    worst = std::max(worst, std::sqrt((b.rowwise() - a.row(i)).rowwise().squaredNorm().minCoeff()));
  return worst;
}

// Oracle (brute force): both vertex sets stay within √3·cell of each other, triangles reference
// valid, distinct vertices, and the budget is kept.
TEST(DisplaySimplification, StaysCloseAndKeepsTheBudget) {
  const Mesh bunny = load_mesh(testing::cgal_mesh("bunny00.off"));
  const double size = (bunny.V.colwise().maxCoeff() - bunny.V.colwise().minCoeff()).maxCoeff();
  for (const double fraction : {0.01, 0.03, 0.1}) {
    const double cell = fraction * size;
    const Mesh coarse = cluster_vertices(bunny, cell);
    EXPECT_LT(coarse.face_count(), bunny.face_count());
    EXPECT_LE(one_sided_distance(coarse.V, bunny.V), std::sqrt(3.0) * cell);
    EXPECT_LE(one_sided_distance(bunny.V, coarse.V), std::sqrt(3.0) * cell);
    for (Eigen::Index f = 0; f < coarse.F.rows(); ++f) {
      EXPECT_TRUE((coarse.F.row(f).array() >= 0).all() && (coarse.F.row(f).array() < coarse.V.rows()).all());
      EXPECT_NE(coarse.F(f, 0), coarse.F(f, 1));
      EXPECT_NE(coarse.F(f, 1), coarse.F(f, 2));
      EXPECT_NE(coarse.F(f, 0), coarse.F(f, 2));
    }
  }
  for (const int budget : {500, 5000, 20000}) {
    const Mesh display = simplify_for_display(bunny, budget);
    EXPECT_LE(display.face_count(), budget);
    EXPECT_GT(display.face_count(), budget / 4) << "the bisection should get close to the budget";
  }
  EXPECT_EQ(simplify_for_display(bunny, bunny.face_count()).F, bunny.F);
}

}  // namespace
}  // namespace reconfig::geometry
