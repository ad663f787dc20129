// Linkage kinematics benchmarks (LinkEdit §5.1): time per kinematic step of the Strandbeest
// with 3 and 10 leg pairs, symbolic vs. the Newton baseline on the same machine, and a
// full 360-sample cycle with state derivatives.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <numbers>

#include "reconfig/linkage/linkage_file.h"
#include "reconfig/linkage/newton_kinematics.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace {

using namespace reconfig::linkage;

constexpr double kDegree = std::numbers::pi / 180;

Linkage strandbeest(int pairs) {
  const auto dir = std::filesystem::path(__FILE__).parent_path().parent_path() / "examples" / "linkages";
  return read_linkage(dir / ("strandbeest_" + std::to_string(pairs) + ".json"));
}

// One kinematic step: all joint positions at the next motor angle (1° further).
void BM_SymbolicStep(benchmark::State& state) {
  const Linkage linkage = strandbeest(static_cast<int>(state.range(0)));
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  Eigen::Matrix2Xd X;
  double angle = 0;
  for (auto _ : state) {
    angle += kDegree;
    if (!kinematics.solve(angle, X)) state.SkipWithError("reconstruction failed");
    benchmark::DoNotOptimize(X.data());
  }
  state.counters["joints"] = static_cast<double>(linkage.joints.size());
}
BENCHMARK(BM_SymbolicStep)->Arg(3)->Arg(10)->Unit(benchmark::kMicrosecond);

// The baseline: rigid bodies with pin constraints, Newton warm-started from the last step.
void BM_NewtonStep(benchmark::State& state) {
  const Linkage linkage = strandbeest(static_cast<int>(state.range(0)));
  NewtonKinematics newton(linkage);
  Eigen::Matrix2Xd X;
  double angle = linkage.initial_motor_angle();
  int iterations = 0, steps = 0;
  for (auto _ : state) {
    angle += kDegree;
    int used = 0;
    if (!newton.solve(angle, X, &used)) state.SkipWithError("Newton did not converge");
    iterations += used, ++steps;
    benchmark::DoNotOptimize(X.data());
  }
  state.counters["newton_iterations"] = static_cast<double>(iterations) / std::max(1, steps);
  state.counters["unknowns"] = newton.unknowns();
}
BENCHMARK(BM_NewtonStep)->Arg(3)->Arg(10)->Unit(benchmark::kMicrosecond);

// Positions and ∂x/∂x̄ at 360 motor angles (one full cycle).
void BM_CycleWithDerivatives(benchmark::State& state) {
  const Linkage linkage = strandbeest(static_cast<int>(state.range(0)));
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  Eigen::Matrix2Xd X;
  StateDerivatives D;
  for (auto _ : state) {
    for (int s = 0; s < 360; ++s)
      if (!kinematics.solve(s * kDegree, X, D)) state.SkipWithError("reconstruction failed");
    benchmark::DoNotOptimize(X.data());
  }
}
BENCHMARK(BM_CycleWithDerivatives)->Arg(3)->Arg(10)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
