#include "shaping_script.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

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

/// carve PART by B[,C…] [offset E] [grid H] [from T0] [to T1] [timeout S]
std::string carve(HeadlessFrontend& frontend, const std::vector<std::string>& args) {
  Studio& studio = frontend.studio();
  if (!studio.document()) return "no design is open";
  if (args.size() < 3 || args[1] != "by")
    return "carve needs PART by B[,C…] [offset E] [grid H] [from T0] [to T1] [timeout S]";
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
    else if (args[i] == "from") settings.from = value;
    else if (args[i] == "to") settings.to = value;
    else if (args[i] == "timeout") timeout = value;
    else return fmt::format("unknown carve option \"{}\" (offset, grid, from, to, timeout)", args[i]);
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

/// carve-window PART [interval K] [by B[,C…]] [offset E] [grid H] [from T0] [to T1]: Collisions >
/// Carve… on PART, then its settings (`interval K`: over PART's K-th collision interval, 0 first).
std::string carve_window(HeadlessFrontend& frontend, const std::vector<std::string>& args) {
  Studio& studio = frontend.studio();
  if (!studio.document()) return "no design is open";
  if (args.empty()) return "carve-window needs PART [interval K] [by B[,C…]] [offset E] [grid H] [from T0] [to T1]";
  const int part = studio.document()->scene().find_part(args[0]);
  if (part < 0) return fmt::format("no part \"{}\"", args[0]);
  studio.select_part(part);
  studio.shaping().show_carve_window(studio);
  if (!studio.shaping().carve_window()) return studio.status();
  ShapingPanel::CarveSettings settings = *studio.shaping().carve_window();
  for (std::size_t i = 1; i < args.size(); i += 2) {
    if (i + 1 >= args.size()) return fmt::format("after \"{}\": a value", args[i]);
    double value = 0;
    if (args[i] == "by") settings.carvers = split_commas(args[i + 1]);
    else if (!parse_number(args[i + 1], value)) return fmt::format("after \"{}\": a number", args[i]);
    else if (args[i] == "interval") {
      const auto intervals = studio.shaping().part_intervals(studio);
      if (value < 0 || value >= double(intervals.size()) || value != std::floor(value))
        return fmt::format("{} has {} collision intervals here: no interval {}", args[0], intervals.size(), args[i + 1]);
      studio.shaping().choose_interval(studio, intervals[std::size_t(value)]);
      settings = *studio.shaping().carve_window();
    } else if (args[i] == "offset") settings.offset = value;
    else if (args[i] == "grid") settings.grid = value;
    else if (args[i] == "from") settings.from = value;
    else if (args[i] == "to") settings.to = value;
    else return fmt::format("unknown carve-window option \"{}\" (interval, by, offset, grid, from, to)", args[i]);
  }
  if (!studio.shaping().set_carve_window(studio, settings)) return studio.status();
  frontend.run_frame();
  return "";
}

/// wait-carve-preview [S]: frames until the Carve window's preview is shown (default 60 s).
std::string wait_carve_preview(HeadlessFrontend& frontend, const std::vector<std::string>& args) {
  Studio& studio = frontend.studio();
  double timeout = 60;
  if (args.size() > 1 || (args.size() == 1 && !parse_number(args[0], timeout))) return "wait-carve-preview [seconds]";
  if (!studio.shaping().carve_window()) return "the Carve window is not open (carve-window PART)";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(timeout * 1000));
  while (!studio.shaping().carve_preview(studio)) {
    if (std::chrono::steady_clock::now() > deadline) return fmt::format("no carve preview within {} s", timeout);
    if (!studio.shaping().carve_preview_computing() && !studio.shaping().carve_window())
      return "the Carve window closed";
    frontend.run_frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  frontend.run_frame();  // drawn
  return "";
}

}  // namespace

bool perform_shaping_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args,
                            std::string& problem) {
  Studio& studio = frontend.studio();
  problem.clear();
  if (action == "carve") {
    problem = carve(frontend, args);
  } else if (action == "carve-window") {
    problem = carve_window(frontend, args);
  } else if (action == "wait-carve-preview") {
    problem = wait_carve_preview(frontend, args);
  } else if (action == "expect-carve-preview") {
    const bool none = !args.empty() && args[0] == "none";
    const auto mesh = studio.shaping().carve_preview(studio);
    const bool shown = mesh && !mesh->empty();
    if (shown == none)
      problem = shown ? fmt::format("expected no carve preview, {} triangles are drawn", mesh->face_count())
                      : "expected the Carve window's swept-volume preview drawn";
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
