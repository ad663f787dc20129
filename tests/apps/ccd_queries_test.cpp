// `reconfig ccd-queries FILE.csv --kind vf|ee` (FORMATS.md): answers on query files written
// here with exactly known answers — random exact rational contacts (some not representable as
// doubles), separated and near-miss configurations, numerators and denominators beyond 2^64 —
// and one-line errors with line numbers for malformed files.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

using testing::run_reconfig;
namespace fs = std::filesystem;

/// A rational num/den with small integers (den > 0).
struct Rational {
  std::int64_t num = 0, den = 1;
};
Rational operator+(Rational a, Rational b) { return {a.num * b.den + b.num * a.den, a.den * b.den}; }
Rational operator-(Rational a, Rational b) { return {a.num * b.den - b.num * a.den, a.den * b.den}; }
Rational operator*(Rational a, Rational b) { return {a.num * b.num, a.den * b.den}; }

using Point = std::array<Rational, 3>;
Point operator+(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point operator-(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point operator*(Rational s, const Point& a) { return {s * a[0], s * a[1], s * a[2]}; }
Point integer_point(int x, int y, int z) { return {Rational{x, 1}, Rational{y, 1}, Rational{z, 1}}; }

/// One query: 8 points (file order) and its true answer.
struct Query {
  std::array<Point, 8> points;
  bool truth = false;
};

/// `big` multiplies numerator and denominator by 10^30 (> 2^64): same value, long integers.
std::string row(const Point& p, bool truth, bool big) {
  const std::string zeros = big ? std::string(30, '0') : "";
  std::ostringstream out;
  for (int i = 0; i < 3; ++i) {
    if (i) out << ',';
    out << p[i].num << (p[i].num == 0 ? "" : zeros) << ',' << p[i].den << zeros;
  }
  out << ',' << (truth ? 1 : 0) << '\n';
  return out.str();
}

fs::path write_queries(const std::vector<Query>& queries, const std::string& name, bool big = false) {
  const fs::path path = testing::fresh_temp_dir() / name;
  std::ofstream out(path);
  for (const Query& q : queries)
    for (const Point& p : q.points) out << row(p, q.truth, big);
  return path;
}

std::vector<char> answers(const std::string& out) {
  std::vector<char> result;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) result.push_back(line == "1" ? 1 : line == "0" ? 0 : 2);
  return result;
}

/// Random vertex–face queries with exactly known answers. Hits: the vertex passes exactly
/// through a point of the moving triangle at time t* (with t* and the barycentric weights in
/// thirds when `thirds`, so coordinates are not doubles). Misses: the vertex stays above
/// z = 2 while the triangle stays below z = 0, or (near miss) passes 1/64 outside an edge.
std::vector<Query> random_vf(std::mt19937& rng, int count, bool thirds) {
  std::uniform_int_distribution<int> coord(-100, 100);
  std::uniform_int_distribution<int> small(1, 5);
  std::vector<Query> queries;
  for (int n = 0; n < count; ++n) {
    Query q;
    const int kind = n % 3;
    for (int k : {1, 2, 3, 5, 6, 7}) q.points[k] = integer_point(coord(rng), coord(rng), coord(rng));
    if (kind == 0) {  // exact hit
      const Rational t = thirds ? Rational{small(rng) % 2 + 1, 3} : Rational{small(rng), 8};
      const Rational w1 = thirds ? Rational{1, 3} : Rational{small(rng), 16};
      const Rational w2 = thirds ? Rational{small(rng) % 2, 3} : Rational{small(rng), 16};
      Point at[3];
      for (int i = 0; i < 3; ++i) at[i] = q.points[1 + i] + t * (q.points[5 + i] - q.points[1 + i]);
      const Point x = at[0] + w1 * (at[1] - at[0]) + w2 * (at[2] - at[0]);
      const Point dir = integer_point(coord(rng), coord(rng), coord(rng));
      q.points[0] = x - t * dir;
      q.points[4] = x + (Rational{1, 1} - t) * dir;
      q.truth = true;
    } else if (kind == 1) {  // separated by the slab 0 < z < 2
      for (int k : {1, 2, 3, 5, 6, 7}) q.points[k][2] = Rational{-std::abs(q.points[k][2].num), 1};
      q.points[0] = integer_point(coord(rng), coord(rng), 2 + std::abs(coord(rng)));
      q.points[4] = integer_point(coord(rng), coord(rng), 2);
    } else {  // near miss: a still triangle in z = 0, the vertex crosses it just outside edge a–b
      q.points[1] = q.points[5] = integer_point(0, 0, 0);
      q.points[2] = q.points[6] = integer_point(64, 0, 0);
      q.points[3] = q.points[7] = integer_point(0, 64, 0);
      const int x = small(rng) * 10;
      q.points[0] = {Rational{x, 1}, Rational{-1, 64}, Rational{coord(rng) % 50 + 51, 1}};
      q.points[4] = {Rational{x, 1}, Rational{-1, 64}, Rational{-(coord(rng) % 50 + 51), 1}};
    }
    queries.push_back(q);
  }
  return queries;
}

TEST(CcdQueriesCli, RandomVertexFaceQueriesAgreeWithTheirExactAnswers) {
  std::mt19937 rng(11);
  for (const bool thirds : {false, true}) {
    const std::vector<Query> queries = random_vf(rng, 90, thirds);
    const auto run = run_reconfig("ccd-queries " + write_queries(queries, "vf.csv").string() + " --kind vf");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::vector<char> got = answers(run.out);
    ASSERT_EQ(got.size(), queries.size());
    for (size_t i = 0; i < queries.size(); ++i) EXPECT_EQ(got[i], queries[i].truth) << "query " << i << " thirds " << thirds;
    EXPECT_NE(run.err.find("90 vf queries, 30 hits"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("0 false positives, 0 false negatives"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("median"), std::string::npos) << run.err;
    // Thirds are not doubles: those queries go through the rounded-input margin.
    EXPECT_EQ(run.err.find("; 0 queries with inexact") == std::string::npos, thirds) << run.err;
  }
}

TEST(CcdQueriesCli, BigIntegersParseExactly) {
  std::mt19937 rng(12);
  const std::vector<Query> queries = random_vf(rng, 30, false);
  const auto small = run_reconfig("ccd-queries " + write_queries(queries, "small.csv").string() + " --kind vf");
  const auto big = run_reconfig("ccd-queries " + write_queries(queries, "big.csv", true).string() + " --kind vf");
  ASSERT_EQ(big.exit_code, 0) << big.err;
  EXPECT_EQ(big.out, small.out);
  for (size_t i = 0; i < queries.size(); ++i) EXPECT_EQ(answers(big.out)[i], queries[i].truth);
  // Dyadic values scaled by 10^30 are still exact doubles.
  EXPECT_NE(big.err.find("; 0 queries with inexact"), std::string::npos) << big.err;
}

TEST(CcdQueriesCli, EdgeEdgeQueries) {
  // Edge a along x at z = 0; edge b along y at height z = 1 − 2t (crossing at t = 1/2); then b
  // shifted just past a's end (miss); then crossing exactly at a's end with thirds (hit).
  auto p = [](Rational x, Rational y, Rational z) { return Point{x, y, z}; };
  const Rational zero{0, 1}, one{1, 1}, minus{-1, 1};
  std::vector<Query> queries;
  Query cross;
  cross.points = {p(minus, zero, zero), p(one, zero, zero), p(zero, minus, one), p(zero, one, one),
                  p(minus, zero, zero), p(one, zero, zero), p(zero, minus, minus), p(zero, one, minus)};
  cross.truth = true;
  queries.push_back(cross);
  Query past = cross;
  for (int k : {2, 3, 6, 7}) past.points[k][0] = Rational{1025, 1024};
  past.truth = false;
  queries.push_back(past);
  Query end = cross;
  for (int k : {1, 5}) end.points[k][0] = Rational{1, 3};
  for (int k : {2, 3, 6, 7}) end.points[k][0] = Rational{1, 3};
  end.truth = true;
  queries.push_back(end);
  const auto run = run_reconfig("ccd-queries " + write_queries(queries, "ee.csv", true).string() + " --kind ee");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "1\n0\n1\n");
  EXPECT_NE(run.err.find("3 ee queries, 2 hits"), std::string::npos) << run.err;
}

TEST(CcdQueriesCli, TruthColumnIsOnlyCompared) {
  std::mt19937 rng(13);
  std::vector<Query> queries = random_vf(rng, 3, false);  // hit, separated, near miss
  for (Query& q : queries) q.truth = !q.truth;
  const auto run = run_reconfig("ccd-queries " + write_queries(queries, "lies.csv").string() + " --kind vf");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "1\n0\n0\n");
  EXPECT_NE(run.err.find("1 false positives, 2 false negatives"), std::string::npos) << run.err;
}

TEST(CcdQueriesCli, ShippedExamplesAnswerAsTheirTruthColumns) {
  const fs::path examples = testing::source_dir() / "examples" / "ccd-queries";
  const auto vf = run_reconfig("ccd-queries " + (examples / "vertex-face.csv").string() + " --kind vf");
  ASSERT_EQ(vf.exit_code, 0) << vf.err;
  EXPECT_EQ(vf.out, "1\n0\n1\n0\n");
  EXPECT_NE(vf.err.find("0 false positives, 0 false negatives; 1 queries with inexact"), std::string::npos) << vf.err;
  const auto ee = run_reconfig("ccd-queries " + (examples / "edge-edge.csv").string() + " --kind ee");
  ASSERT_EQ(ee.exit_code, 0) << ee.err;
  EXPECT_EQ(ee.out, "1\n0\n");
  EXPECT_NE(ee.err.find("0 false positives, 0 false negatives"), std::string::npos) << ee.err;
}

/// Writes `text` and runs the command on it.
testing::CommandResult run_on(const std::string& text, const std::string& kind = "vf") {
  const fs::path path = testing::fresh_temp_dir() / "bad.csv";
  std::ofstream(path) << text;
  return run_reconfig("ccd-queries " + path.string() + " --kind " + kind);
}

std::string rows(int n) {
  std::string text;
  for (int i = 0; i < n; ++i) text += "1,2,3,4,5,6,0\n";
  return text;
}

int count_lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

TEST(CcdQueriesCli, BadInputExitsTwoNamingTheLine) {
  struct Case {
    std::string text, expect;
  };
  const std::vector<Case> cases = {
      {rows(3) + "1,2,3,4,5,6\n" + rows(4), "line 4"},                  // 6 columns
      {rows(2) + "1,2,3,4,5,6,0,7\n" + rows(5), "line 3"},              // 8 columns
      {rows(5) + "1,0,3,4,5,6,0\n" + rows(2), "line 6"},                // zero denominator
      {rows(1) + "1,2,x,4,5,6,0\n" + rows(6), "line 2"},                // not a number
      {rows(1) + "1.5,2,3,4,5,6,0\n" + rows(6), "line 2"},              // not an integer
      {rows(7) + "1,2,3,4,5,6,\n", "line 8"},                           // empty truth
      {rows(8) + rows(3), "line 11"},                                   // 11 rows
  };
  for (const Case& c : cases) {
    const auto run = run_on(c.text);
    EXPECT_EQ(run.exit_code, 2) << c.text;
    EXPECT_EQ(count_lines(run.err), 1) << run.err;
    EXPECT_NE(run.err.find(c.expect), std::string::npos) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
  EXPECT_EQ(run_reconfig("ccd-queries /nonexistent/q.csv --kind vf").exit_code, 2);
  EXPECT_EQ(run_on(rows(8), "xx").exit_code, 2);
  const auto empty = run_on("");
  EXPECT_EQ(empty.exit_code, 0) << empty.err;
  EXPECT_TRUE(empty.out.empty());
}

}  // namespace
}  // namespace reconfig
