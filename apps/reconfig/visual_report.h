#pragma once
/// @file
/// `reconfig check SCENE --report DIR/`: a self-contained HTML page (DIR/index.html) with the
/// images beside it — per transition a timeline strip of its collision intervals (SVG), per
/// interval its parts, times, energy and a picture from its best view at its severity time
/// with ghosts of the moving parts (PNG) — readable on a phone; no scripts, nothing fetched.

#include <filesystem>
#include <string>
#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/render/best_view.h"
#include "reconfig/resolve/interval_energy.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::cli {

/// What `check` found, one entry per checked transition and interval.
struct ReportInput {
  std::string scene_file;
  std::string method;  ///< how it was found, for people
  std::vector<collision::TransitionCollisions> transitions;
  std::vector<std::vector<resolve::IntervalEnergy>> energies;
  std::vector<std::vector<render::BestView>> views;
};

/// Writes DIR/index.html, DIR/report.md (`markdown`) and the images (creating DIR). Needs a
/// current OpenGL context. Throws `reconfig::InputError` naming a file that cannot be written.
void write_visual_report(const std::filesystem::path& dir, const scene::Reconfigurable& scene,
                         const ReportInput& input, const std::string& markdown);

}  // namespace reconfig::cli
