// `reconfig bench SUITE`: runs the Google Benchmark suite and reports it with baseline ratios.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

class BenchCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(testing::binary_dir() / "bin" / "bench_linkage"))
      GTEST_SKIP() << "configured with RECONFIG_BUILD_BENCH=OFF";
  }
};

TEST_F(BenchCli, LinkageSuiteReportsTheNewtonRatioAsJson) {
  const auto run = testing::run_reconfig("bench linkage --filter 'Step/3' --min-time 0.01 --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report["suite"], "linkage");
  ASSERT_EQ(report["benchmarks"].size(), 2u);  // symbolic and Newton, 3 leg pairs
  ASSERT_EQ(report["ratios"].size(), 1u);
  EXPECT_EQ(report["ratios"][0]["subject"], "BM_SymbolicStep/3");
  EXPECT_EQ(report["ratios"][0]["baseline"], "BM_NewtonStep/3");
  EXPECT_GT(report["ratios"][0]["speedup"].get<double>(), 10.0);  // the issue asks for ≥ 100× (docs/benchmarks.md)
}

TEST_F(BenchCli, TableForPeople) {
  const auto run = testing::run_reconfig("bench linkage --filter 'Step/3' --min-time 0.01");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("BM_SymbolicStep/3"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("faster than BM_NewtonStep/3"), std::string::npos) << run.out;
}

TEST_F(BenchCli, UnknownSuiteIsBadInput) {
  const auto run = testing::run_reconfig("bench nonsense");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no such benchmark suite"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace reconfig
