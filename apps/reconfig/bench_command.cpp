// reconfig bench SUITE — runs a benchmark suite (build/bin/bench_<suite>, Google Benchmark) and
// prints its table with the ratios against the baselines the issues name; --json for scripts.

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "command.h"
#include "reconfig/common/input_error.h"

namespace reconfig::cli {
namespace {

namespace fs = std::filesystem;

struct BenchOptions {
  std::string suite;
  bool json = false;
  std::string filter;
  double min_time = 0.5;
};

/// A baseline comparison: for every benchmark named `subject` + suffix, the one named
/// `baseline` + the same suffix, reported as baseline time / subject time.
struct Comparison {
  std::string subject, baseline, label;
};

const std::map<std::string, std::vector<Comparison>>& comparisons() {
  static const std::map<std::string, std::vector<Comparison>> table = {
      {"linkage", {{"BM_SymbolicStep", "BM_NewtonStep", "symbolic step vs Newton over rigid bodies"}}},
      {"collision", {{"BM_FullDetection", "BM_ReferenceCheck", "engine vs reference check (same time resolution)"}}},
  };
  return table;
}

fs::path own_folder() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::current_path() : self.parent_path();
}

/// The part of a benchmark name after its family ("/3", "/scene:0/dop:28" → "/scene:0").
std::string suffix_of(const std::string& name, const std::string& family) { return name.substr(family.size()); }

std::string strip_dop(const std::string& suffix) {
  const auto at = suffix.find("/dop:");
  return at == std::string::npos ? suffix : suffix.substr(0, at);
}

int run_bench(const BenchOptions& options) {
  std::string name = options.suite;
  for (char& c : name)
    if (c == '-') c = '_';
  const fs::path binary = own_folder() / ("bench_" + name);
  if (!fs::exists(binary))
    throw InputError(binary.string(), "", "no such benchmark suite (configure with -DRECONFIG_BUILD_BENCH=ON)");
  std::string command = binary.string() + " --benchmark_format=json --benchmark_min_time=" +
                        fmt::format("{}", options.min_time);
  if (options.filter.find('\'') != std::string::npos) throw InputError("", "--filter", "must not contain a quote");
  if (!options.filter.empty()) command += " '--benchmark_filter=" + options.filter + "'";
  command += " 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) throw InputError(binary.string(), "", "cannot run the benchmark");
  std::string output;
  std::array<char, 4096> buffer{};
  while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError(binary.string(), "", fmt::format("the benchmark failed (status {})", status));
  const nlohmann::json report = nlohmann::json::parse(output, nullptr, false);
  if (report.is_discarded() || !report.contains("benchmarks"))
    throw InputError(binary.string(), "", "the benchmark printed no JSON report");

  // Ratios against the named baselines.
  nlohmann::ordered_json ratios = nlohmann::ordered_json::array();
  const auto found = comparisons().find(options.suite);
  if (found != comparisons().end())
    for (const Comparison& comparison : found->second)
      for (const auto& subject : report["benchmarks"]) {
        const std::string subject_name = subject["name"];
        if (subject_name.rfind(comparison.subject, 0) != 0) continue;
        const std::string key = strip_dop(suffix_of(subject_name, comparison.subject));
        for (const auto& baseline : report["benchmarks"]) {
          const std::string baseline_name = baseline["name"];
          if (baseline_name.rfind(comparison.baseline, 0) != 0 ||
              strip_dop(suffix_of(baseline_name, comparison.baseline)) != key)
            continue;
          // Both in the same unit after conversion to nanoseconds.
          const auto nanoseconds = [](const nlohmann::json& b) {
            const std::string unit = b["time_unit"];
            const double scale = unit == "s" ? 1e9 : unit == "ms" ? 1e6 : unit == "us" ? 1e3 : 1.0;
            return b["real_time"].get<double>() * scale;
          };
          ratios.push_back({{"label", comparison.label},
                            {"subject", subject_name},
                            {"baseline", baseline_name},
                            {"speedup", nanoseconds(baseline) / nanoseconds(subject)}});
        }
      }

  if (options.json) {
    nlohmann::ordered_json out;
    out["suite"] = options.suite;
    out["context"] = report["context"];
    out["benchmarks"] = report["benchmarks"];
    out["ratios"] = ratios;
    fmt::print("{}\n", out.dump(2));
    return kExitOk;
  }
  const auto& context = report["context"];
  fmt::print("{} — {} CPUs, {}\n\n", options.suite, context.value("num_cpus", 0), context.value("date", ""));
  fmt::print("{:<44} {:>14} {:>14}\n", "benchmark", "real time", "CPU time");
  for (const auto& b : report["benchmarks"]) {
    const std::string unit = b["time_unit"];
    fmt::print("{:<44} {:>11.3f} {:<2} {:>11.3f} {:<2}\n", b["name"].get<std::string>(), b["real_time"].get<double>(),
               unit, b["cpu_time"].get<double>(), unit);
  }
  if (!ratios.empty()) fmt::print("\n");
  for (const auto& r : ratios)
    fmt::print("{}: {} is {:.1f}× {} than {}\n", r["label"].get<std::string>(), r["subject"].get<std::string>(),
               r["speedup"].get<double>() >= 1 ? r["speedup"].get<double>() : 1 / r["speedup"].get<double>(),
               r["speedup"].get<double>() >= 1 ? "faster" : "slower", r["baseline"].get<std::string>());
  return kExitOk;
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* command =
      app.add_subcommand("bench", "Run a benchmark suite and print its table and baseline ratios (--json for scripts)");
  command->add_option("suite", options->suite, "linkage, collision or narrow-phase")->required();
  command->add_flag("--json", options->json, "Print the results as JSON");
  command->add_option("--filter", options->filter, "Only benchmarks whose name matches this regular expression");
  command->add_option("--min-time", options->min_time, "Seconds each benchmark runs at least")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->callback([options, &exit_code] { exit_code = run_bench(*options); });
}

}  // namespace reconfig::cli
