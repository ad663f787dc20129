#include "collision_settings.h"

#include <fmt/format.h>

#include "reconfig/collision/detector_settings.h"
#include "reconfig/scene/edits.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

constexpr const auto& kFamilies = collision::kDopFamilies;

int family_index(collision::DopFamily family) {
  for (std::size_t i = 0; i < kFamilies.size(); ++i)
    if (kFamilies[i] == family) return static_cast<int>(i);
  return 1;
}

/// "8-DOP (boxes)", "28-DOP", ...: the combo box's items.
const std::vector<std::string>& family_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const collision::DopFamily family : kFamilies)
      all.push_back(fmt::format("{}-DOP{}", collision::halfspace_count(family), family == collision::DopFamily::k8 ? " (boxes)" : ""));
    return all;
  }();
  return names;
}

bool family_name(void* /*data*/, int index, const char** text) {
  *text = family_names()[index].c_str();
  return true;
}

std::string describe(const collision::DetectorOptions& options) {
  return fmt::format("tolerance {:g}, {}-DOP, {}, frames of {:g}{}{}{}", options.tolerance,
                     collision::halfspace_count(options.dop),
                     options.box_resolution > 0 ? fmt::format("box grid {:g} %", 100 * options.box_resolution)
                                                : std::string("exact boxes"),
                     options.frame, options.conservative ? ", conservative" : "",
                     options.touching_collides ? ", touching collides" : "",
                     options.clearance > 0 ? fmt::format(", clearance {:g}", options.clearance) : std::string());
}

void hint(const char* text) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace

bool Studio::set_detector_options(const collision::DetectorOptions& options) {
  const scene::CollisionSettings settings = collision::settings_of(options);
  if (const std::string problem = settings.problem(); !problem.empty()) {
    set_status(fmt::format("collision settings not changed: {}", problem), true);
    return false;
  }
  if (!document_) {
    options_.collisions.detector = options;  // for the designs opened next, unless they have their own
  } else if (settings != document_->scene().collision) {
    // Saved with the design, as one undoable edit.
    if (const std::string refused = document_->execute(scene::set_collision_settings(settings)); !refused.empty()) {
      set_status(fmt::format("collision settings not changed: {}", refused), true);
      return false;
    }
  }
  set_status(fmt::format("collision settings: {}", describe(detector_options())));
  return true;
}

const collision::DetectorOptions& Studio::detector_options() const {
  return document_ ? document_->detector_options() : options_.collisions.detector;
}

void CollisionSettingsWindow::show(const Studio& studio) { draft_ = studio.detector_options(); }

namespace {

/// The window's fields over `draft`.
void draw_fields(collision::DetectorOptions& draft) {
  ImGui::SetNextItemWidth(160);
  ImGui::InputDouble("Tolerance", &draft.tolerance, 0, 0, "%.6g");
  hint("Largest distance between the sampled motion and the true one, in scene units.\n"
       "Smaller: more time samples, slower detection.");
  int family = family_index(draft.dop);
  ImGui::SetNextItemWidth(160);
  if (ImGui::Combo("Bounding volumes", &family, family_name, nullptr, static_cast<int>(kFamilies.size())))
    draft.dop = kFamilies[family];
  hint("The k-DOP family of the spacetime hierarchies: 28 is usually fastest.");
  double percent = 100 * draft.box_resolution;
  ImGui::SetNextItemWidth(160);
  if (ImGui::InputDouble("Box grid (% of part size)", &percent, 0, 0, "%.4g")) draft.box_resolution = percent / 100;
  hint("Collision boxes are rounded outward to a grid of this size; 0 gives exact boxes (slower on deep overlaps).");
  ImGui::SetNextItemWidth(160);
  ImGui::InputDouble("Frame (fraction of a transition)", &draft.frame, 0, 0, "%.4g");
  hint("The 3D view's boxes cover at most one frame of time each.");
  ImGui::Checkbox("Conservative", &draft.conservative);
  hint("Also report near misses that the true motion (between the samples) may turn into collisions:\n"
       "no collision is ever missed, at the price of some that are not there.");
  ImGui::Checkbox("Touching collides", &draft.touching_collides);
  hint("Also report parts that only touch (surfaces within the contact tolerance, interiors not\n"
       "overlapping beyond it) as collisions: a drawer in its runner, a box on a table.");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  ImGui::InputDouble("Clearance (0: none)", &draft.clearance, 0, 0, "%.6g");
  hint("Also report, in amber, where two parts come closer than this distance without colliding:\n"
       "the manufacturing gaps a design needs.");
  ImGui::SetNextItemWidth(160);
  ImGui::InputDouble("Contact tolerance (0: default)", &draft.contact, 0, 0, "%.6g");
  hint("Parts that meet by no more than this distance only touch. 0: 1e-6 of the design's size.");
}

}  // namespace

void CollisionSettingsWindow::draw(Studio& studio) {
  if (!draft_) return;
  bool open = true;
  const Layout& layout = studio.layout();
  ImGui::SetNextWindowPos(ImVec2(layout.viewport_min.x + 24, layout.viewport_min.y + 48), ImGuiCond_Appearing);
  if (ImGui::Begin("Collision settings", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    draw_fields(*draft_);
    if (ImGui::Button("Apply")) studio.set_detector_options(*draft_);
    ImGui::SameLine();
    if (ImGui::Button("Close")) open = false;
  }
  ImGui::End();
  if (!open) draft_.reset();
}

}  // namespace reconfig::studio
