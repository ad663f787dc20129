#pragma once
// Helpers shared by the linkage tests: example files, random linkages.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "reconfig/linkage/linkage.h"
#include "reconfig/linkage/linkage_file.h"
#include "support/test_data.h"

namespace reconfig::linkage::test {

inline Linkage example(const std::string& name) {
  return read_linkage(testing::source_dir() / "examples" / "linkages" / name);
}

inline const char* const kExamples[] = {"jansen.json",           "strandbeest_3.json",    "strandbeest_10.json",
                                        "klann.json",            "chebyshev_lambda.json", "peaucellier_lipkin.json",
                                        "four_bar_crank_rocker.json", "triad_complex_loop.json"};

namespace detail {

inline Eigen::Vector2d circles(const Eigen::Vector2d& p, double rp, const Eigen::Vector2d& q, double rq, bool left) {
  const Eigen::Vector2d d = q - p;
  const double d2 = d.squaredNorm();
  const double a = (d2 + rp * rp - rq * rq) / (2 * d2);
  const double h = std::sqrt(std::max(0.0, rp * rp / d2 - a * a)) * (left ? 1 : -1);
  return p + a * d + h * Eigen::Vector2d(-d.y(), d.x());
}

}  // namespace detail

inline Linkage random_crank_rocker(std::mt19937& rng, double angle) {
  std::uniform_real_distribution<double> unit(0, 1);
  // Crank s shortest; ground g, coupler c, rocker r with s + max ≤ sum of the other two.
  const double s = 1, g = 2.5 + 2 * unit(rng);
  double c = 0, r = 0;
  do {
    c = 1.5 + 4 * unit(rng);
    r = 1.5 + 4 * unit(rng);
  } while (!(s + std::max({g, c, r}) + 0.3 <= g + c + r - std::max({g, c, r})));
  const bool left = unit(rng) < 0.5;
  Linkage linkage;
  const Eigen::Vector2d A(0, 0), D(g, 0), B(s * std::cos(angle), s * std::sin(angle));
  const Eigen::Vector2d C = detail::circles(B, c, D, r, left);
  const double b = (0.2 + unit(rng)) * (unit(rng) < 0.5 ? -1 : 1);
  const Eigen::Vector2d E = B + (2 * unit(rng) - 0.5) * (C - B) + b * Eigen::Vector2d(B.y() - C.y(), C.x() - B.x());
  linkage.joints = {{"A", A, true}, {"D", D, true}, {"B", B, false}, {"C", C, false}, {"E", E, false}};
  linkage.links = {{0, 2}, {2, 3, 4}, {1, 3}};
  linkage.motor = {0, 2};
  return linkage;
}

inline Linkage complex_loop() {
  Linkage linkage;
  linkage.joints = {{"O", {0, 0}, true},   {"C", {1, 0}, false},   {"G", {5, 0}, true},
                    {"H", {3, 5}, true},   {"P1", {3, 1}, false},  {"P2", {5, 2.5}, false},
                    {"P3", {3.5, 3}, false}};
  linkage.links = {{0, 1}, {1, 4}, {2, 5}, {3, 6}, {4, 5, 6}};
  linkage.motor = {0, 1};
  return linkage;
}

}  // namespace reconfig::linkage::test
