#include "shaping_script.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <sstream>

#include "studio.h"

namespace reconfig::studio {
namespace {

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> items;
  std::istringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

bool parse_number(const std::string& text, double& value) {
  try {
    std::size_t used = 0;
    value = std::stod(text, &used);
    return used == text.size() && std::isfinite(value);
  } catch (const std::exception&) {
    return false;
  }
}

/// carve PART by B[,C…] [offset E] [grid H] [timeout S]
std::string carve(HeadlessFrontend& frontend, const std::vector<std::string>& args) {
  Studio& studio = frontend.studio();
  if (!studio.document()) return "no design is open";
  if (args.size() < 3 || args[1] != "by") return "carve needs PART by B[,C…] [offset E] [grid H] [timeout S]";
  const int part = studio.document()->scene().find_part(args[0]);
  if (part < 0) return fmt::format("no part \"{}\"", args[0]);
  ShapingPanel::CarveSettings settings;
  settings.carvers = split_commas(args[2]);
  double timeout = 120;
  for (std::size_t i = 3; i < args.size(); i += 2) {
    double value = 0;
    if (i + 1 >= args.size() || !parse_number(args[i + 1], value))
      return fmt::format("after \"{}\": a number", args[i]);
    if (args[i] == "offset") settings.offset = value;
    else if (args[i] == "grid") settings.grid = value;
    else if (args[i] == "timeout") timeout = value;
    else return fmt::format("unknown carve option \"{}\" (offset, grid, timeout)", args[i]);
  }
  studio.select_part(part);
  if (!studio.shaping().start_carve(studio, settings)) return studio.status();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(timeout * 1000));
  while (studio.shaping().carving()) {
    if (std::chrono::steady_clock::now() > deadline) {
      studio.shaping().cancel_carve(studio);
      return fmt::format("the carve did not finish within {} s", timeout);
    }
    frontend.run_frame();
  }
  frontend.run_frame();
  if (studio.status().rfind("carved ", 0) != 0) return studio.status();
  return "";
}

}  // namespace

bool perform_shaping_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args,
                            std::string& problem) {
  Studio& studio = frontend.studio();
  problem.clear();
  if (action == "carve") {
    problem = carve(frontend, args);
  } else if (action == "envelope") {
    if (args.size() != 1 || (args[0] != "on" && args[0] != "off")) problem = "envelope on|off";
    else studio.shaping().set_envelope_shown(args[0] == "on");
    frontend.run_frame();
  } else if (action == "expect-envelope") {
    const bool none = !args.empty() && args[0] == "none";
    const auto mesh = studio.shaping().envelope(studio);
    const bool drawn = mesh && !mesh->empty();
    if (drawn == none)
      problem = drawn ? fmt::format("expected no envelope, {} triangles are drawn", mesh->face_count())
                      : "expected the swept envelope drawn (View > Swept envelope, a part selected, a transition open)";
  } else {
    return false;
  }
  return true;
}

}  // namespace reconfig::studio
