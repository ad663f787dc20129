// The k-DOP families' axes, and the additions-only values of points along them.

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "reconfig/collision/kdop.h"

namespace reconfig::collision {
namespace {

template <DopFamily family>
void expect_sign_directions(int dims, bool time_axis) {
  constexpr auto signs = dop_axis_signs<family>();
  std::set<std::array<int, 4>> seen;
  for (int i = 0; i < static_cast<int>(signs.size()); ++i) {
    const std::array<int, 4>& v = signs[i];
    int first = 0, nonzero = 0;
    for (int d = 0; d < 4; ++d) {
      ASSERT_TRUE(v[d] >= -1 && v[d] <= 1);
      if (v[d] != 0 && nonzero++ == 0) first = v[d];
    }
    EXPECT_EQ(first, 1) << "axis " << i << ": one of each ± pair, first nonzero component +1";
    EXPECT_TRUE(seen.insert(v).second) << "axis " << i << " repeated";
    if (i < dims) {
      EXPECT_EQ(nonzero, 1) << "the unit axes come first: x, y, z (then t)";
    }
    const bool is_time_axis = time_axis && i + 1 == static_cast<int>(signs.size());
    for (int d = dims; d < 4 && !is_time_axis; ++d) EXPECT_EQ(v[d], 0);
  }
  if (time_axis) {
    EXPECT_EQ(signs.back(), (std::array<int, 4>{0, 0, 0, 1}));
  }
  // Spatial boxes are read from the first three axes in every family.
  for (int d = 0; d < 3; ++d) EXPECT_EQ(signs[d][d], 1);
}

TEST(Kdop, AxisFamiliesAreTheSignDirections) {
  expect_sign_directions<DopFamily::k8>(3, true);
  expect_sign_directions<DopFamily::k28>(3, true);    // 13 spatial: (3³ − 1) / 2
  expect_sign_directions<DopFamily::k80>(4, false);   // every one of (3⁴ − 1) / 2
  EXPECT_EQ(dop_axis_signs<DopFamily::k28>().size(), 14u);
  EXPECT_EQ(dop_axis_signs<DopFamily::k80>().size(), 40u);
}

template <DopFamily family>
void expect_axis_values_match_dot_products(std::mt19937& rng) {
  const auto& axes = dop_axes<family>();
  std::uniform_real_distribution<double> real(-1e3, 1e3);
  std::uniform_int_distribution<int> integer(-1 << 20, 1 << 20);
  for (int trial = 0; trial < 2000; ++trial) {
    // Integer coordinates: every sum is exact, so both ways agree bit for bit; real ones agree
    // to the rounding of three additions.
    const bool exact = trial % 2 == 0;
    const Eigen::Vector3d p = exact ? Eigen::Vector3d(integer(rng), integer(rng), integer(rng))
                                    : Eigen::Vector3d(real(rng), real(rng), real(rng));
    const double t = exact ? integer(rng) : real(rng);
    const auto values = axis_values<family>(p, t);
    for (int j = 0; j < axis_count(family); ++j) {
      const double dot = axes[j].template head<3>().dot(p) + axes[j][3] * t;
      if (exact) {
        EXPECT_EQ(values[j], dot) << "axis " << j;
      } else {
        EXPECT_NEAR(values[j], dot, 1e-12 * (p.cwiseAbs().sum() + std::abs(t))) << "axis " << j;
      }
    }
  }
  // The Kdop of two points spans their values.
  Kdop<family> dop;
  const Eigen::Vector3d p(0.25, -3, 7.5), q(-1.5, 2, 0.125);
  dop.extend(p, 0.5);
  dop.extend(q, 0.75);
  const auto at_p = axis_values<family>(p, 0.5), at_q = axis_values<family>(q, 0.75);
  for (int j = 0; j < axis_count(family); ++j) {
    EXPECT_EQ(dop.lo[j], std::min(at_p[j], at_q[j]));
    EXPECT_EQ(dop.hi[j], std::max(at_p[j], at_q[j]));
  }
}

TEST(Kdop, AxisValuesAreTheDotProductsWithTheAxes) {
  std::mt19937 rng(2811);
  expect_axis_values_match_dot_products<DopFamily::k8>(rng);
  expect_axis_values_match_dot_products<DopFamily::k28>(rng);
  expect_axis_values_match_dot_products<DopFamily::k80>(rng);
}

}  // namespace
}  // namespace reconfig::collision
