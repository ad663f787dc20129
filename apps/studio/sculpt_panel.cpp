// Sculpting in the studio: the inspector's Sculpt section shapes the selected part with a swept
// tool (the sculpt module, Sweepers) — pick a tool, its size, coating and place in the part's
// frame, one stroke (translate, scale or rotate), the mirror plane — and applies it as one
// undoable edit of the part's mesh; the collision service then re-detects the part's
// transitions.

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>

#include "reconfig/geometry/bounding_box.h"
#include "reconfig/scene/edits.h"
#include "reconfig/sculpt/sculpt_stroke.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

/// The settings' tool, or a message saying what is wrong with them.
std::optional<sculpt::Tool> make_tool(const Studio::SculptSettings& s, std::string& problem) {
  if (!(s.coating > 0)) problem = "the coating must be > 0";
  else if (!(s.size.x() > 0) || (s.shape != 0 && s.shape != 2 && !(s.size.minCoeff() > 0)) || (s.shape == 2 && s.size.y() < 0))
    problem = "the tool's sizes must be > 0";
  if (!problem.empty()) return std::nullopt;
  switch (s.shape) {
    case 0: return sculpt::Tool::sphere(s.size.x(), s.center, s.coating);
    case 1: return sculpt::Tool::box(s.size, s.center, s.coating);
    case 2: return sculpt::Tool::capsule(s.size.x(), s.size.y(), s.center, s.coating);
    default: return sculpt::Tool::ellipsoid(s.size, s.center, s.coating);
  }
}

std::optional<sculpt::ToolMotion> make_motion(const Studio::SculptSettings& s, std::string& problem) {
  if (s.stroke == 0) return sculpt::ToolMotion::translation(s.translation);
  if (s.stroke == 1) {
    if (!(s.factor > 0)) problem = "the scaling factor must be > 0";
    return problem.empty() ? std::optional(sculpt::ToolMotion::scaling(s.factor, s.center)) : std::nullopt;
  }
  if (!(s.axis.norm() > 0)) problem = "the rotation axis must not be zero";
  return problem.empty() ? std::optional(sculpt::ToolMotion::rotation(s.axis, s.degrees * M_PI / 180, s.center))
                         : std::nullopt;
}

}  // namespace

bool Studio::sculpt_selected_part() {
  if (!document_ || selected_part_ < 0) {
    set_status("sculpt: select a part first", true);
    return false;
  }
  const scene::Part& part = document_->scene().parts[selected_part_];
  std::string problem;
  const std::optional<sculpt::Tool> tool = make_tool(sculpt_settings_, problem);
  const std::optional<sculpt::ToolMotion> motion = tool ? make_motion(sculpt_settings_, problem) : std::nullopt;
  if (!motion) {
    set_status("sculpt: " + problem, true);
    return false;
  }
  sculpt::StrokeOptions options;
  options.mirror.axis = sculpt_settings_.mirror;
  options.remesh = {sculpt_settings_.remesh, sculpt_settings_.remesh / 4};
  geometry::Mesh mesh = part.mesh;
  Eigen::MatrixX3d no_normals(0, 3);
  const sculpt::StrokeResult result = sculpt::sculpt_mesh({{*tool, *motion}}, options, mesh, no_normals);
  if (!result.applied) {
    set_status(fmt::format("sculpt: {} refused the stroke: {}", part.name, result.refusal), true);
    return false;
  }
  const std::string name = part.name;  // `part` does not outlive the edit
  if (!execute(scene::replace_part_mesh(name, std::move(mesh)))) return false;
  set_status(fmt::format("sculpted {}: {} sub-steps, {} vertices moved, least det J {:.3g}", name, result.substeps,
                         result.vertices_moved, result.min_jacobian_determinant));
  return true;
}

void Studio::draw_sculpt_section() {
  if (!document_ || selected_part_ < 0) return;
  SculptSettings& s = sculpt_settings_;
  ImGui::Separator();
  if (!ImGui::CollapsingHeader("Sculpt")) return;
  const char* shapes[] = {"sphere", "box", "capsule", "ellipsoid"};
  ImGui::Combo("tool", &s.shape, shapes, 4);
  const char* size_label = s.shape == 0 ? "radius" : s.shape == 1 ? "edges" : s.shape == 2 ? "radius, length" : "semi-axes";
  ImGui::InputScalarN(size_label, ImGuiDataType_Double, s.size.data(), s.shape == 0 ? 1 : s.shape == 2 ? 2 : 3, nullptr,
                      nullptr, "%.4f");
  ImGui::InputDouble("coating", &s.coating, 0, 0, "%.4f");
  ImGui::InputScalarN("tool center", ImGuiDataType_Double, s.center.data(), 3, nullptr, nullptr, "%.4f");
  ImGui::SameLine();
  if (ImGui::SmallButton("part center"))
    s.center = geometry::bounding_box(document_->scene().parts[selected_part_].mesh.V).center();
  const char* strokes[] = {"translate", "scale", "rotate"};
  ImGui::Combo("stroke", &s.stroke, strokes, 3);
  if (s.stroke == 0) ImGui::InputScalarN("by", ImGuiDataType_Double, s.translation.data(), 3, nullptr, nullptr, "%.4f");
  if (s.stroke == 1) ImGui::InputDouble("factor", &s.factor, 0, 0, "%.4f");
  if (s.stroke == 2) {
    ImGui::InputScalarN("axis", ImGuiDataType_Double, s.axis.data(), 3, nullptr, nullptr, "%.3f");
    ImGui::InputDouble("degrees", &s.degrees, 0, 0, "%.2f");
  }
  int mirror = s.mirror + 1;
  const char* mirrors[] = {"no mirror", "mirror x = 0", "mirror y = 0", "mirror z = 0"};
  if (ImGui::Combo("mirror", &mirror, mirrors, 4)) s.mirror = mirror - 1;
  ImGui::InputDouble("remesh edge", &s.remesh, 0, 0, "%.4f");
  if (ImGui::Button("Apply stroke")) sculpt_selected_part();
  ImGui::TextDisabled("in the part's rest frame; each stroke is one undoable edit");
}

}  // namespace reconfig::studio
