// reconfig bench SUITE — runs a benchmark suite (build/bin/bench_<suite>, Google Benchmark) and
// prints its table with the ratios against the baselines the issues name; --json for scripts.
// The collision suite also gets a summary per scene (engine with each DOP family, update after
// a key edit, reference check, FCL at the engine's proxy times, FCL at the same guarantee, FCL's
// continuous collision and what it misses, and the ratios), in the tables and as "summary" in
// the JSON.

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>
#include <tuple>

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
      {"collision",
       {{"BM_FullDetection", "BM_ReferenceCheck", "engine vs reference check (same time resolution)"},
        {"BM_FullDetection", "BM_FclPerStep", "engine vs FCL 0.7 at the engine's ~33 proxy times (no guarantee between samples)"},
        {"BM_FullDetection", "BM_FclGuaranteedStep",
         "engine vs FCL 0.7 at the same guarantee (no vertex moves more than the tolerance between samples)"},
        {"BM_FullDetection", "BM_FclContinuous", "engine vs FCL 0.7 continuous collision per proxy step (first contacts only)"}}},
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

/// What a subject and its baseline have in common: the suffix without the DOP family, the
/// every-contact switch and Google Benchmark's run options ("/scene:0/dop:28/all:0/real_time"
/// → "/scene:0").
std::string comparison_key(const std::string& suffix) {
  std::string key, segment;
  std::istringstream in(suffix);
  while (std::getline(in, segment, '/')) {
    if (segment.empty()) continue;
    bool option = false;
    for (const char* prefix : {"dop:", "all:", "real_time", "process_time", "iterations:", "min_time:", "repeats:", "threads:"})
      option = option || segment.rfind(prefix, 0) == 0;
    if (!option) key += "/" + segment;
  }
  return key;
}

/// A benchmark's real time (or, with `field` "cpu_time", its CPU time) in nanoseconds.
double nanoseconds(const nlohmann::json& b, const char* field = "real_time") {
  const std::string unit = b["time_unit"];
  const double scale = unit == "s" ? 1e9 : unit == "ms" ? 1e6 : unit == "us" ? 1e3 : 1.0;
  return b[field].get<double>() * scale;
}

/// "0.123 s", "45.6 ms", "7.89 µs" from nanoseconds.
std::string human_time(double ns) {
  if (ns >= 1e9) return fmt::format("{:.3g} s", ns / 1e9);
  if (ns >= 1e6) return fmt::format("{:.3g} ms", ns / 1e6);
  if (ns >= 1e3) return fmt::format("{:.3g} µs", ns / 1e3);
  return fmt::format("{:.3g} ns", ns);
}

/// "12× faster" / "3.4× slower" for a speedup (baseline time / subject time).
std::string human_ratio(double speedup) {
  return speedup >= 1 ? fmt::format("{:.3g}× faster", speedup) : fmt::format("{:.3g}× slower", 1 / speedup);
}

/// The collision suite per scene: one row per "scene:N" with the times (ns, null if not run)
/// of the engine per DOP family, the update, the reference and FCL, and the ratios.
nlohmann::ordered_json collision_summary(const nlohmann::json& benchmarks) {
  std::map<std::string, nlohmann::ordered_json> rows;  // by scene key
  std::vector<std::string> order;
  const auto row_for = [&](const std::string& key, const nlohmann::json& b) -> nlohmann::ordered_json& {
    if (!rows.count(key)) {
      order.push_back(key);
      nlohmann::ordered_json row;
      row["scene"] = key.substr(key.find(':') + 1);
      row["label"] = b.value("label", "");
      for (const char* counter : {"triangles", "parts", "samples"}) row[counter] = b.value(counter, 0.0);
      for (const char* column :
           {"engine_ns", "dop8_ns", "dop80_ns", "all_contacts_ns", "update_ns", "reference_ns", "fcl_ns", "fcl_all_contacts_ns",
            "engine_cpu_ns", "fcl_cpu_ns", "fcl_guaranteed_ns", "fcl_guaranteed_all_contacts_ns", "fcl_guaranteed_cpu_ns",
            "fcl_ccd_ns", "fcl_ccd_cpu_ns"})
        row[column] = nullptr;
      rows[key] = row;
    }
    return rows[key];
  };
  for (const auto& b : benchmarks) {
    const std::string name = b["name"];
    const auto slash = name.find('/');
    if (slash == std::string::npos || b.value("run_type", "iteration") != "iteration") continue;
    const std::string family = name.substr(0, slash), suffix = name.substr(slash);
    const std::string key = comparison_key(suffix);
    if (key.rfind("/scene:", 0) != 0) continue;
    std::string column;
    if (family == "BM_FullDetection") {
      const auto dop = suffix.find("/dop:");
      const std::string k = dop == std::string::npos ? "28" : suffix.substr(dop + 5, suffix.find('/', dop + 1) - dop - 5);
      column = suffix.find("/all:1") != std::string::npos ? "all_contacts_ns" : k == "28" ? "engine_ns" : "dop" + k + "_ns";
    } else if (family == "BM_UpdateAfterKeyEdit") {
      column = "update_ns";
    } else if (family == "BM_ReferenceCheck") {
      column = "reference_ns";
    } else if (family == "BM_FclPerStep") {
      column = "fcl_ns";
    } else if (family == "BM_FclAllContactsPerStep") {
      column = "fcl_all_contacts_ns";
    } else if (family == "BM_FclGuaranteedStep") {
      column = suffix.find("/all:1") != std::string::npos ? "fcl_guaranteed_all_contacts_ns" : "fcl_guaranteed_ns";
    } else if (family == "BM_FclContinuous") {
      column = "fcl_ccd_ns";
    } else {
      continue;
    }
    nlohmann::ordered_json& row = row_for(key, b);
    row[column] = nanoseconds(b);
    // CPU time of the whole process (the benchmarks measure it over all threads): steadier than
    // wall-clock time on a machine whose steal time comes and goes.
    if (column == "engine_ns" || column == "fcl_ns" || column == "fcl_guaranteed_ns" || column == "fcl_ccd_ns")
      row[column.substr(0, column.size() - 3) + "_cpu_ns"] = nanoseconds(b, "cpu_time");
    if (family == "BM_FullDetection" && column == "engine_ns") row["contacts"] = b.value("contacts", 0.0);
    if (family == "BM_FclPerStep") {
      row["fcl_colliding_samples"] = b.value("colliding_samples", 0.0);
      row["fcl_missed_by_engine"] = b.value("missed_by_engine", 0.0);
    }
    if (column == "fcl_guaranteed_ns") {
      row["fcl_guaranteed_samples"] = b.value("fcl_samples", 0.0);
      row["fcl_guaranteed_colliding_samples"] = b.value("colliding_samples", 0.0);
      row["fcl_guaranteed_missed_by_engine"] = b.value("missed_by_engine", 0.0);
    }
    if (column == "fcl_ccd_ns")
      for (const char* counter : {"pair_steps", "engine_intervals", "starts_found", "starts_missed", "intervals_missed",
                                  "ends_unreported", "extra_contacts", "pairs", "pairs_missed", "first_contact_error"})
        row[std::string("ccd_") + counter] = b.value(counter, 0.0);
  }
  nlohmann::ordered_json summary = nlohmann::ordered_json::array();
  for (const std::string& key : order) {
    nlohmann::ordered_json& row = rows[key];
    constexpr std::array<std::tuple<const char*, const char*, const char*>, 9> kRatios = {
        {{"engine_vs_reference", "reference_ns", "engine_ns"},
         {"engine_vs_fcl", "fcl_ns", "engine_ns"},
         {"engine_vs_fcl_all_contacts", "fcl_all_contacts_ns", "engine_ns"},
         {"engine_vs_fcl_cpu", "fcl_cpu_ns", "engine_cpu_ns"},
         {"engine_vs_fcl_guaranteed", "fcl_guaranteed_ns", "engine_ns"},
         {"engine_vs_fcl_guaranteed_all_contacts", "fcl_guaranteed_all_contacts_ns", "engine_ns"},
         {"engine_vs_fcl_guaranteed_cpu", "fcl_guaranteed_cpu_ns", "engine_cpu_ns"},
         {"engine_vs_fcl_ccd", "fcl_ccd_ns", "engine_ns"},
         {"engine_vs_fcl_ccd_cpu", "fcl_ccd_cpu_ns", "engine_cpu_ns"}}};
    for (const auto& [column, baseline, subject] : kRatios)
      row[column] = row[subject].is_null() || row[baseline].is_null()
                        ? nlohmann::ordered_json(nullptr)
                        : nlohmann::ordered_json(row[baseline].get<double>() / row[subject].get<double>());
    summary.push_back(row);
  }
  return summary;
}

void print_collision_summary(const nlohmann::ordered_json& summary) {
  if (summary.empty()) return;
  const auto time = [](const nlohmann::ordered_json& v) { return v.is_null() ? std::string("—") : human_time(v.get<double>()); };
  const auto ratio = [](const nlohmann::ordered_json& v) { return v.is_null() ? std::string("—") : human_ratio(v.get<double>()); };
  fmt::print("\nper scene (real time; engine = 28-DOP full detection at 1 mm; samples = the engine's time resolution;\n"
             "engine/FCL CPU: the ratio of their processes' CPU times over all threads)\n");
  fmt::print("(FCL: at the engine's ~33 proxy times, no guarantee between samples: whether each pair of parts\n"
             "intersects at each sample; FCL all: every intersecting triangle pair)\n");
  fmt::print("{:<5} {:<36} {:>9} {:>5} {:>7} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>17} {:>15} {:>15} {:>15}\n", "scene",
             "", "triangles", "parts", "samples", "engine", "8-DOP", "80-DOP", "update", "reference", "FCL", "FCL all",
             "engine/reference", "engine/FCL", "engine/FCL all", "engine/FCL CPU");
  for (const auto& row : summary)
    fmt::print("{:<5} {:<36} {:>9} {:>5} {:>7} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>17} {:>15} {:>15} {:>15}\n",
               row["scene"].get<std::string>(), row["label"].get<std::string>().substr(0, 36),
               static_cast<long>(row["triangles"].get<double>()), static_cast<long>(row["parts"].get<double>()),
               static_cast<long>(row["samples"].get<double>()), time(row["engine_ns"]), time(row["dop8_ns"]),
               time(row["dop80_ns"]), time(row["update_ns"]), time(row["reference_ns"]), time(row["fcl_ns"]),
               time(row["fcl_all_contacts_ns"]), ratio(row["engine_vs_reference"]), ratio(row["engine_vs_fcl"]),
               ratio(row["engine_vs_fcl_all_contacts"]), ratio(row["engine_vs_fcl_cpu"]));
}

/// The baselines that make the engine's promise: FCL discrete at the step where no vertex moves
/// more than the tolerance, and FCL's continuous collision per proxy step, with what it misses.
void print_honest_baselines(const nlohmann::ordered_json& summary) {
  bool any = false;
  for (const auto& row : summary) any = any || !row["fcl_guaranteed_ns"].is_null() || !row["fcl_ccd_ns"].is_null();
  if (!any) return;
  const auto time = [](const nlohmann::ordered_json& v) { return v.is_null() ? std::string("—") : human_time(v.get<double>()); };
  const auto ratio = [](const nlohmann::ordered_json& v) { return v.is_null() ? std::string("—") : human_ratio(v.get<double>()); };
  const auto count = [](const nlohmann::ordered_json& row, const char* key) {
    return row.contains(key) ? fmt::format("{}", static_cast<long>(row[key].get<double>())) : std::string("—");
  };
  fmt::print("\nFCL at the same guarantee (discrete, no vertex moves more than the tolerance between samples) and\n"
             "FCL continuous collision per proxy step (first contact of each step; misses: interval starts not given /\n"
             "intervals without any FCL contact / ends never given / FCL contacts in no engine interval)\n");
  fmt::print("{:<5} {:>9} {:>8} {:>9} {:>9} {:>15} {:>15} {:>15} {:>9} {:>15} {:>15} {:>13}\n", "scene", "engine", "samples",
             "FCL", "FCL all", "engine/FCL", "engine/FCL CPU", "engine/FCL all", "FCL CCD", "engine/CCD", "engine/CCD CPU",
             "CCD misses");
  for (const auto& row : summary)
    fmt::print("{:<5} {:>9} {:>8} {:>9} {:>9} {:>15} {:>15} {:>15} {:>9} {:>15} {:>15} {:>13}\n", row["scene"].get<std::string>(),
               time(row["engine_ns"]), count(row, "fcl_guaranteed_samples"), time(row["fcl_guaranteed_ns"]),
               time(row["fcl_guaranteed_all_contacts_ns"]), ratio(row["engine_vs_fcl_guaranteed"]),
               ratio(row["engine_vs_fcl_guaranteed_cpu"]), ratio(row["engine_vs_fcl_guaranteed_all_contacts"]),
               time(row["fcl_ccd_ns"]), ratio(row["engine_vs_fcl_ccd"]), ratio(row["engine_vs_fcl_ccd_cpu"]),
               fmt::format("{}/{}/{}/{}", count(row, "ccd_starts_missed"), count(row, "ccd_intervals_missed"),
                           count(row, "ccd_ends_unreported"), count(row, "ccd_extra_contacts")));
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
        const std::string key = comparison_key(suffix_of(subject_name, comparison.subject));
        for (const auto& baseline : report["benchmarks"]) {
          const std::string baseline_name = baseline["name"];
          if (baseline_name.rfind(comparison.baseline, 0) != 0 ||
              comparison_key(suffix_of(baseline_name, comparison.baseline)) != key)
            continue;
          ratios.push_back({{"label", comparison.label},
                            {"subject", subject_name},
                            {"baseline", baseline_name},
                            {"speedup", nanoseconds(baseline) / nanoseconds(subject)}});
        }
      }

  const nlohmann::ordered_json summary =
      options.suite == "collision" ? collision_summary(report["benchmarks"]) : nlohmann::ordered_json::array();
  if (options.json) {
    nlohmann::ordered_json out;
    out["suite"] = options.suite;
    out["context"] = report["context"];
    out["benchmarks"] = report["benchmarks"];
    out["ratios"] = ratios;
    if (options.suite == "collision") out["summary"] = summary;
    fmt::print("{}\n", out.dump(2));
    return kExitOk;
  }
  const auto& context = report["context"];
  fmt::print("{} — {} CPUs, {}{}\n\n", options.suite, context.value("num_cpus", 0), context.value("date", ""),
             context.contains("load_avg") && context["load_avg"].is_array() && !context["load_avg"].empty()
                 ? fmt::format(", load average {:.2f}", context["load_avg"][0].get<double>())
                 : std::string());
  fmt::print("{:<56} {:>14} {:>14}\n", "benchmark", "real time", "CPU time");
  for (const auto& b : report["benchmarks"]) {
    const std::string unit = b["time_unit"];
    fmt::print("{:<56} {:>11.3f} {:<2} {:>11.3f} {:<2}\n", b["name"].get<std::string>(), b["real_time"].get<double>(),
               unit, b["cpu_time"].get<double>(), unit);
  }
  print_collision_summary(summary);
  print_honest_baselines(summary);
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
