// Linkage kinematics benchmarks (LinkEdit §5.1): time per kinematic step of the Strandbeest
// with 3 and 10 leg pairs, symbolic vs. the Newton baseline on the same machine, and a
// full 360-sample cycle with state derivatives.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <numbers>

#include "reconfig/linkage/linkage_edit.h"
#include "reconfig/linkage/linkage_file.h"
#include "reconfig/linkage/newton_kinematics.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace {

using namespace reconfig::linkage;

constexpr double kDegree = std::numbers::pi / 180;

Linkage strandbeest(int pairs) {
  const auto dir = std::filesystem::path(RECONFIG_SOURCE_DIR) / "examples" / "linkages";
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

// One evaluation of the edit energy and its gradient (72 samples: trajectory of every foot,
// envelope, regularization, singularity barrier) — what one L-BFGS step costs.
void BM_EditEnergyGradient(benchmark::State& state) {
  const Linkage linkage = strandbeest(static_cast<int>(state.range(0)));
  EditSettings settings;
  const std::vector<double> angles = edit_sample_angles(linkage, settings.samples);
  EditObjectives objectives;
  for (const TrackingPoint& point : linkage.tracking_points)
    objectives.trajectories.push_back({point.joint, joint_trajectory(linkage, point.joint, angles), 1.0});
  objectives.envelope = EditObjectives::Envelope{{-150, -100}, {150, 60}, 1.0};
  EditEnergy energy(linkage, objectives, settings);
  const Eigen::Matrix2Xd X0 = linkage.initial_positions();
  Eigen::Matrix2Xd G;
  for (auto _ : state) benchmark::DoNotOptimize(energy(X0, &G));
}
BENCHMARK(BM_EditEnergyGradient)->Arg(3)->Arg(10)->Unit(benchmark::kMillisecond);

// A whole edit of the Jansen leg: drag the upper joint, keep the foot path.
void BM_EditJansenDrag(benchmark::State& state) {
  const auto dir = std::filesystem::path(RECONFIG_SOURCE_DIR) / "examples" / "linkages";
  const Linkage linkage = read_linkage(dir / "jansen.json");
  const int upper = linkage.find_joint("U"), foot = linkage.find_joint("P");
  EditObjectives objectives;
  objectives.drags.push_back({upper, {-30, 35}, std::nullopt, 1.0});
  objectives.trajectories.push_back({foot, joint_trajectory(linkage, foot, edit_sample_angles(linkage, 72)), 10.0});
  EditSettings settings;
  settings.max_iterations = 50;
  for (auto _ : state) benchmark::DoNotOptimize(edit_linkage(linkage, objectives, settings).energy_after);
}
BENCHMARK(BM_EditJansenDrag)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
