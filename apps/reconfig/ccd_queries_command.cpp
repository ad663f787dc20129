// reconfig ccd-queries FILE.csv --kind vf|ee — runs continuous-collision queries in the public
// CCD benchmark format (FORMATS.md) through the narrow phase's vertex–face / edge–edge tests:
// one line `1`/`0` per query on stdout, a timing summary (and agreement with the file's truth
// column) on stderr.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "command.h"
#include "reconfig/collision/ccd_primitives.h"
#include "reconfig/collision/ccd_query_file.h"

namespace reconfig::cli {
namespace {

struct CcdQueriesOptions {
  std::string file;
  std::string kind;
  double tolerance = 1e-6;
};

int run_ccd_queries(const CcdQueriesOptions& options) {
  const std::vector<collision::CcdQuery> queries = collision::read_ccd_queries(options.file);
  const bool vertex_face = options.kind == "vf";

  std::string out;
  out.reserve(queries.size() * 2);
  std::vector<double> micros;
  micros.reserve(queries.size());
  int hits = 0, false_positives = 0, false_negatives = 0, inexact = 0;
  double total = 0;
  for (const collision::CcdQuery& query : queries) {
    collision::PrimitiveCcdOptions ccd;
    ccd.tolerance = options.tolerance;
    ccd.earliest = false;  // only whether they touch
    // Coordinates that are not doubles were rounded: widen every decision by how far that can
    // move F (vertex–face: vertex + up to three face weights of magnitude ≤ 1; edge–edge: two
    // convex combinations), so the answer holds for the exact rational input.
    ccd.separation = (vertex_face ? 4 : 2) * query.conversion_error;
    inexact += query.conversion_error > 0;
    const auto& x = query.points;
    const auto start = std::chrono::steady_clock::now();
    const collision::PrimitiveCcdResult r =
        vertex_face ? collision::vertex_face_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], ccd)
                    : collision::edge_edge_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], ccd);
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    micros.push_back(us);
    total += us;
    hits += r.hit;
    false_positives += r.hit && !query.truth;
    false_negatives += !r.hit && query.truth;
    out += r.hit ? "1\n" : "0\n";
  }
  std::fwrite(out.data(), 1, out.size(), stdout);

  double median = 0;
  if (!micros.empty()) {
    const auto middle = micros.begin() + static_cast<std::ptrdiff_t>(micros.size() / 2);
    std::nth_element(micros.begin(), middle, micros.end());
    median = *middle;
  }
  fmt::print(stderr,
             "ccd-queries: {} {} queries, {} hits; total {:.3f} ms, median {:.3f} us/query; "
             "vs truth column: {} false positives, {} false negatives; {} queries with inexact "
             "(rounded) coordinates; tolerance {:g}\n",
             queries.size(), options.kind, hits, total / 1000, median, false_positives, false_negatives, inexact,
             options.tolerance);
  return kExitOk;
}

}  // namespace

void add_ccd_queries_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<CcdQueriesOptions>();
  CLI::App* command = app.add_subcommand(
      "ccd-queries", "Run vertex-face / edge-edge CCD queries from a benchmark CSV (8 rows per query); prints 1/0 per query");
  command->add_option("file", options->file, "Query file: rows x_num,x_den,y_num,y_den,z_num,z_den,truth")->required();
  command->add_option("--kind", options->kind, "vf (vertex-face) or ee (edge-edge)")
      ->required()
      ->check(CLI::IsMember({"vf", "ee"}));
  command->add_option("--tolerance", options->tolerance,
                      "Distance tolerance of the test (model units): hits closer than this may be reported")
      ->check(CLI::PositiveNumber);
  command->callback([options, &exit_code] { exit_code = run_ccd_queries(*options); });
}

}  // namespace reconfig::cli
