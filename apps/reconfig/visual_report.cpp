#include "visual_report.h"

#include <fmt/format.h>

#include "interval_view.h"
#include "reconfig/common/input_error.h"
#include "reconfig/common/write_atomically.h"
#include "reconfig/render/renderer.h"
#include "reconfig/render/scene_draw_list.h"
#include "reconfig/view/ghost_sampling.h"
#include "reconfig/view/scene_bounds.h"

namespace reconfig::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kPictureWidth = 800, kPictureHeight = 600;

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string part_list(const scene::Reconfigurable& scene, const collision::CollisionInterval& ci) {
  std::string names;
  for (int p : ci.parts) {
    if (!names.empty()) names += " × ";
    names += scene.parts[p].name;
  }
  return names;
}

void write_text(const fs::path& path, const std::string& text) {
  write_atomically(path, [&](std::ostream& out) { out << text; });
}

/// The transition's time line 0 … 1 with one row per interval: a red bar over its extent and a
/// dark mark at its severity time.
std::string timeline_svg(const scene::Reconfigurable& scene, const collision::TransitionCollisions& transition,
                         const std::vector<resolve::IntervalEnergy>& energies) {
  constexpr double kWidth = 800, kLeft = 20, kRight = 780, kRow = 26, kTop = 30;
  const double height = kTop + kRow * std::max<std::size_t>(transition.intervals.size(), 1) + 10;
  const auto x = [&](double t) { return kLeft + t * (kRight - kLeft); };
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {} {}\" width=\"{}\" height=\"{}\" "
      "font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n",
      kWidth, height, kWidth, height);
  for (int tick = 0; tick <= 10; ++tick) {
    const double tx = x(tick / 10.0);
    svg += fmt::format("<line x1=\"{0}\" y1=\"18\" x2=\"{0}\" y2=\"{1}\" stroke=\"#ddd\"/>\n", tx, height - 6);
    svg += fmt::format("<text x=\"{}\" y=\"13\" text-anchor=\"middle\" fill=\"#555\">{:.1f}</text>\n", tx, tick / 10.0);
  }
  for (std::size_t i = 0; i < transition.intervals.size(); ++i) {
    const collision::CollisionInterval& ci = transition.intervals[i];
    const double y = kTop + kRow * static_cast<double>(i);
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"18\" rx=\"3\" fill=\"#e2412f\"/>\n", x(ci.t0), y,
                       std::max(2.0, x(ci.t1) - x(ci.t0)));
    const double severe = x(energies[i].severity_time);
    svg += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#222\" stroke-width=\"3\"/>\n", severe,
                       y - 2, y + 20);
    const bool right = ci.t1 < 0.6;  // the label beside the bar, where there is room
    svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"{}\" fill=\"#222\">{}. {}</text>\n",
                       right ? x(ci.t1) + 6 : x(ci.t0) - 6, y + 14, right ? "start" : "end", i + 1,
                       escaped(part_list(scene, ci)));
  }
  if (transition.intervals.empty())
    svg += fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#2a7d2a\">collision-free</text>\n", x(0), kTop + 14);
  return svg + "</svg>\n";
}

/// The interval at its severity time from its best view: its box, its parts selected, ghosts
/// of the moving parts before and after.
render::Image interval_picture(render::Renderer& renderer, const scene::Reconfigurable& scene, int transition,
                               const collision::CollisionInterval& ci, double time, const render::BestView& view) {
  render::SceneDrawRequest request;
  request.transition = transition;
  request.time = time;
  request.selected = ci.parts;
  request.boxes = {ci.box};
  request.ghosts = view::ghost_samples({.current = time, .count = 2, .spacing = 0.08});
  Eigen::AlignedBox3d bounds = view::scene_bounds_at(scene, transition, time);
  for (const view::GhostSample& ghost : request.ghosts) bounds.extend(view::scene_bounds_at(scene, transition, ghost.time));
  return renderer.render(render::scene_draw_list(scene, request), picture_camera(view, bounds), kPictureWidth,
                         kPictureHeight);
}

constexpr const char* kStyle = R"(
  :root { color-scheme: light; }
  body { font: 16px/1.45 system-ui, sans-serif; margin: 0; color: #222; background: #fff; overflow-wrap: anywhere; }
  main { max-width: 52rem; margin: 0 auto; padding: 1rem; }
  h1 { font-size: 1.5rem; margin: 0.5rem 0; }
  h2 { font-size: 1.2rem; margin-top: 2rem; border-bottom: 1px solid #ddd; }
  h3 { font-size: 1.05rem; margin: 0 0 0.5rem; }
  img { display: block; max-width: 100%; height: auto; border-radius: 4px; }
  .timeline { width: 100%; border: 1px solid #eee; }
  .ci { margin: 1rem 0; padding: 0.75rem; border: 1px solid #e6e6e6; border-radius: 6px; }
  dl { display: grid; grid-template-columns: max-content 1fr; gap: 0.2rem 0.8rem; margin: 0.6rem 0 0; }
  dt { color: #666; }
  dd { margin: 0; }
  .free { color: #2a7d2a; }
  .file, .method { color: #555; }
  code { font-size: 0.95em; }
)";

std::string interval_html(const scene::Reconfigurable& scene, const collision::CollisionInterval& ci, std::size_t i,
                          const resolve::IntervalEnergy& energy, const render::BestView& view,
                          const std::string& picture) {
  const Eigen::Vector3d lo = ci.box.min(), hi = ci.box.max();
  std::string html = fmt::format("<article class=\"ci\">\n<h3>{}. {}</h3>\n", i + 1, escaped(part_list(scene, ci)));
  html += fmt::format("<img src=\"{}\" width=\"{}\" height=\"{}\" alt=\"{} at t = {:.3f}, seen from its best view\">\n",
                      picture, kPictureWidth, kPictureHeight, escaped(part_list(scene, ci)), energy.severity_time);
  html += "<dl>\n";
  html += fmt::format("<dt>time</dt><dd>{:.3f} – {:.3f} (most severe at {:.3f})</dd>\n", ci.t0, ci.t1,
                      energy.severity_time);
  html += fmt::format("<dt>energy</dt><dd>{:.4g} (contour {:.4g}, penetration {:.4g})</dd>\n", energy.energy,
                      energy.contour_energy, energy.penetration_energy);
  html += fmt::format("<dt>where</dt><dd>({:.3f}, {:.3f}, {:.3f}) – ({:.3f}, {:.3f}, {:.3f})</dd>\n", lo.x(), lo.y(),
                      lo.z(), hi.x(), hi.y(), hi.z());
  if (ci.containment) html += "<dt>kind</dt><dd>one inside the other</dd>\n";
  if (ci.possible) html += "<dt>kind</dt><dd>possible: within the tolerance</dd>\n";
  html += fmt::format("<dt>view</dt><dd>{:.0f} % of the collision box in sight</dd>\n",
                      100 * view.pixels.visible_fraction());
  return html + "</dl>\n</article>\n";
}

}  // namespace

void write_visual_report(const fs::path& dir, const scene::Reconfigurable& scene, const ReportInput& input,
                         const std::string& markdown) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw InputError(dir.string(), "", "cannot create the report folder: " + error.message());
  render::Renderer renderer;
  std::size_t count = 0;
  for (const auto& transition : input.transitions) count += transition.intervals.size();
  std::string body = fmt::format("<h1>Collision report</h1>\n<p class=\"file\"><code>{}</code></p>\n",
                                 escaped(input.scene_file));
  body += fmt::format("<p>{} parts, {} states, {} transitions; <span class=\"method\">{}</span>. ", scene.parts.size(),
                      scene.states.size(), scene.transitions.size(), escaped(input.method));
  body += count == 0 ? std::string("<strong class=\"free\">No collisions.</strong></p>\n")
                     : fmt::format("<strong>{} collision interval{}.</strong></p>\n", count, count == 1 ? "" : "s");
  for (std::size_t t = 0; t < input.transitions.size(); ++t) {
    const collision::TransitionCollisions& transition = input.transitions[t];
    const scene::Transition& tr = scene.transitions[transition.transition];
    body += fmt::format("<section>\n<h2>Transition <code>{}</code> ({} → {})</h2>\n", escaped(tr.name),
                        escaped(tr.from), escaped(tr.to));
    const std::string strip = fmt::format("transition-{}-timeline.svg", t + 1);
    write_text(dir / strip, timeline_svg(scene, transition, input.energies[t]));
    body += fmt::format("<img class=\"timeline\" src=\"{}\" alt=\"time line of {}: its collision intervals\">\n", strip,
                        escaped(tr.name));
    if (transition.intervals.empty()) body += "<p class=\"free\">Collision-free.</p>\n";
    for (std::size_t i = 0; i < transition.intervals.size(); ++i) {
      const collision::CollisionInterval& ci = transition.intervals[i];
      const std::string picture = fmt::format("transition-{}-interval-{}.png", t + 1, i + 1);
      render::write_png(dir / picture, interval_picture(renderer, scene, transition.transition, ci,
                                                        input.energies[t][i].severity_time, input.views[t][i]));
      body += interval_html(scene, ci, i, input.energies[t][i], input.views[t][i], picture);
    }
    body += "</section>\n";
  }
  const std::string html = fmt::format(
      "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>Collision report: {}</title>\n"
      "<style>{}</style>\n</head>\n<body>\n<main>\n{}</main>\n</body>\n</html>\n",
      escaped(fs::path(input.scene_file).filename().string()), kStyle, body);
  write_text(dir / "index.html", html);
  write_text(dir / "report.md", markdown);
}

}  // namespace reconfig::cli
