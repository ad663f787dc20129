// Sculpting in the studio (sculpt_panel.h): the inspector's Sculpt section and the sculpt mode's
// strokes, each one undoable edit of the selected part's mesh.

#include "sculpt_panel.h"

#include <fmt/format.h>

#include <cmath>

#include "reconfig/geometry/bounding_box.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/edits.h"
#include "reconfig/sculpt/sculpt_stroke.h"
#include "axis_angle.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

constexpr double kWheelScale = 1.1;  ///< the tool's scaling per wheel step during a stroke
constexpr int kToolSubdivisions = 2;  ///< of the spheres the round tools are drawn with

/// `mesh` with every vertex mapped by `map`.
geometry::Mesh mapped(geometry::Mesh mesh, const auto& map) {
  for (int v = 0; v < mesh.vertex_count(); ++v) mesh.V.row(v) = map(Eigen::Vector3d(mesh.V.row(v))).transpose();
  return mesh;
}

std::optional<sculpt::ToolMotion> make_motion(const SculptPanel::Settings& s, std::string& problem) {
  if (s.stroke == 0) return sculpt::ToolMotion::translation(s.translation);
  if (s.stroke == 1) {
    if (!(s.factor > 0)) problem = "the scaling factor must be > 0";
    return problem.empty() ? std::optional(sculpt::ToolMotion::scaling(s.factor, s.center)) : std::nullopt;
  }
  if (!(s.axis.norm() > 0)) problem = "the rotation axis must not be zero";
  return problem.empty() ? std::optional(sculpt::ToolMotion::rotation(s.axis, s.degrees * M_PI / 180, s.center))
                         : std::nullopt;
}

/// `tool` turned by `rotation` about `pivot` (a point of the part's rest frame that stays).
sculpt::Tool turned(sculpt::Tool tool, const Eigen::Quaterniond& rotation, const Eigen::Vector3d& pivot) {
  sculpt::ToolPose pose = tool.pose();
  pose.rotation = (rotation * pose.rotation).normalized();
  pose.translation = pivot + rotation * (pose.translation - pivot);
  tool.set_pose(pose);
  return tool;
}

/// An ImGui color for ring `axis` (red x, green y, blue z, as the part gizmo's), amber if hot,
/// faint if it cannot be picked.
ImU32 ring_color(int axis, bool hot, bool faint) {
  if (hot) return IM_COL32(250, 200, 30, 255);
  return IM_COL32(axis == 0 ? 230 : 40, axis == 1 ? 190 : 40, axis == 2 ? 240 : 40, faint ? 70 : 255);
}

sculpt::StrokeOptions stroke_options(const SculptPanel::Settings& s) {
  sculpt::StrokeOptions options;
  options.mirror.axis = s.mirror;
  options.remesh = {s.remesh, s.remesh / 4};
  return options;
}

}  // namespace

// ---- the tool ------------------------------------------------------------------------------

std::optional<Eigen::Isometry3d> SculptPanel::part_to_world(const Studio& studio) const {
  const std::optional<motion::Pose> pose = studio.selected_pose();
  if (!pose) return std::nullopt;
  return pose->to_isometry(studio.document()->scene().parts[studio.selected_part()].center);
}

std::optional<sculpt::Tool> SculptPanel::make_tool(const Studio& studio, geometry::Mesh* shape,
                                                   Eigen::Vector3d* origin, std::string& problem) const {
  const Settings& s = settings_;
  const scene::Reconfigurable& scene = studio.document()->scene();
  if (!(s.coating > 0)) problem = "the coating must be > 0";
  else if (s.shape == 4 && (s.tool_part < 0 || s.tool_part >= int(scene.parts.size()) || s.tool_part == studio.selected_part()))
    problem = "pick another part of the design as the tool";
  else if (s.shape != 4 && (!(s.size.x() > 0) || (s.shape != 0 && s.shape != 2 && !(s.size.minCoeff() > 0)) ||
                            (s.shape == 2 && s.size.y() < 0)))
    problem = "the tool's sizes must be > 0";
  if (!problem.empty()) return std::nullopt;
  if (origin) *origin = Eigen::Vector3d::Zero();
  switch (s.shape) {
    case 0:
      if (shape) *shape = geometry::make_sphere(s.size.x(), kToolSubdivisions);
      return turned(sculpt::Tool::sphere(s.size.x(), s.center, s.coating), s.rotation, s.center);
    case 1:
      if (shape) *shape = geometry::make_box(s.size);
      return turned(sculpt::Tool::box(s.size, s.center, s.coating), s.rotation, s.center);
    case 2:
      if (shape) {
        const double half = s.size.y() / 2;
        *shape = mapped(geometry::make_sphere(s.size.x(), kToolSubdivisions), [&](const Eigen::Vector3d& p) {
          return Eigen::Vector3d(p.x(), p.y(), p.z() + (p.z() >= 0 ? half : -half));
        });
      }
      return turned(sculpt::Tool::capsule(s.size.x(), s.size.y(), s.center, s.coating), s.rotation, s.center);
    case 3:
      if (shape)
        *shape = mapped(geometry::make_sphere(1.0, kToolSubdivisions),
                        [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.cwiseProduct(s.size)); });
      return turned(sculpt::Tool::ellipsoid(s.size, s.center, s.coating), s.rotation, s.center);
    default: break;
  }
  // A part baked as the tool, where it is now, in the sculpted part's rest frame.
  const scene::Part& tool_part = scene.parts[s.tool_part];
  const std::optional<Eigen::Isometry3d> to_world = part_to_world(studio);
  const std::optional<motion::Pose> pose =
      studio.active_transition_ >= 0 ? std::optional(scene.pose_at(studio.active_transition_, s.tool_part, studio.time_))
                                     : scene.states[studio.active_state_].pose_of(tool_part.name);
  if (!to_world || !pose) {
    problem = "the tool part has no pose here";
    return std::nullopt;
  }
  const Eigen::Isometry3d to_rest = to_world->inverse() * pose->to_isometry(tool_part.center);
  const BakedToolCache::Baked* baked = baked_tool_.bake(tool_part.mesh, to_rest, s.coating);
  if (!baked) {
    problem = tool_part.name + " is not closed: it cannot be baked as a tool";
    return std::nullopt;
  }
  if (origin) *origin = baked->center;
  if (shape) *shape = baked->mesh;
  return turned(baked->tool, s.rotation, baked->center);
}

std::optional<Eigen::Vector3d> SculptPanel::tool_center(const Studio& studio) const {
  if (stroke_) return stroke_->to_world * stroke_->tool.pose().to_world(stroke_->tool_origin);
  if (!mode_ || !studio.document() || studio.selected_part() < 0) return std::nullopt;
  const std::optional<Eigen::Isometry3d> to_world = part_to_world(studio);
  if (!to_world) return std::nullopt;
  if (settings_.shape != 4) return *to_world * settings_.center;
  std::string problem;
  Eigen::Vector3d origin;
  if (!make_tool(studio, nullptr, &origin, problem)) return std::nullopt;
  return *to_world * origin;
}

void SculptPanel::add_to_draw_list(const Studio& studio, render::DrawList& list) const {
  if (!mode_ || !studio.document() || studio.selected_part() < 0) return;
  geometry::Mesh shape;
  std::string problem;
  std::optional<sculpt::Tool> tool = stroke_ ? std::optional(stroke_->tool) : make_tool(studio, &shape, nullptr, problem);
  const std::optional<Eigen::Isometry3d> to_world = stroke_ ? std::optional(stroke_->to_world) : part_to_world(studio);
  if (!tool || !to_world) return;
  if (stroke_) make_tool(studio, &shape, nullptr, problem);  // the shape in the tool's own frame
  if (shape.empty()) return;
  render::MeshItem item;
  item.V = mapped(shape, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(*to_world * tool->pose().to_world(p)); }).V;
  item.F = shape.F;
  item.color = stroke_ && stroke_->stopped ? Eigen::Vector3f(0.9f, 0.2f, 0.15f) : Eigen::Vector3f(0.95f, 0.6f, 0.15f);
  item.opacity = 0.35f;
  list.meshes.push_back(std::move(item));
}

std::optional<ToolRings> SculptPanel::rings(const Studio& studio) const {
  if (!mode_ || !studio.document() || studio.selected_part() < 0) return std::nullopt;
  std::string problem;
  Eigen::Vector3d origin = stroke_ ? stroke_->tool_origin : Eigen::Vector3d::Zero();
  const std::optional<sculpt::Tool> tool =
      stroke_ ? std::optional(stroke_->tool) : make_tool(studio, nullptr, &origin, problem);
  const std::optional<Eigen::Isometry3d> to_world = stroke_ ? std::optional(stroke_->to_world) : part_to_world(studio);
  if (!tool || !to_world) return std::nullopt;
  // How far the tool reaches from its center: half its box's diagonal, the coating left out.
  const Eigen::Array3d sizes = tool->field_box().sizes().array() - 2 * tool->coating();
  const Eigen::Matrix3d axes = to_world->linear() * tool->pose().rotation.toRotationMatrix();
  const Layout& layout = studio.layout();
  return ToolRings::around(studio.camera(), static_cast<int>(layout.viewport_max.y - layout.viewport_min.y),
                           *to_world * tool->pose().to_world(origin), axes, sizes.max(0).matrix().norm() / 2);
}

std::optional<int> SculptPanel::ring_at(const Studio& studio, const ImVec2& at) const {
  const std::optional<ToolRings> tool_rings = rings(studio);
  return tool_rings ? ring_at(studio, *tool_rings, at) : std::nullopt;
}

std::optional<int> SculptPanel::ring_at(const Studio& studio, const ToolRings& tool_rings, const ImVec2& at) {
  const Layout& layout = studio.layout();
  return tool_rings.hit(studio.camera(), static_cast<int>(layout.viewport_max.x - layout.viewport_min.x),
                        static_cast<int>(layout.viewport_max.y - layout.viewport_min.y),
                        {at.x - layout.viewport_min.x, at.y - layout.viewport_min.y});
}

void SculptPanel::draw_rings(const Studio& studio, ImDrawList* draw) const {
  const std::optional<ToolRings> tool_rings = rings(studio);
  if (!tool_rings) return;
  const int hot = stroke_   ? stroke_->ring.value_or(-1)
                  : placing_ ? -1
                             : ring_at(studio, *tool_rings, ImGui::GetIO().MousePos).value_or(-1);
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<ImVec2> points;
    for (const Eigen::Vector3d& point : tool_rings->ring(axis))
      if (const std::optional<ImVec2> at = studio.viewport_point(point)) points.push_back(*at);
    if (points.size() >= 2)
      draw->AddPolyline(points.data(), static_cast<int>(points.size()),
                        ring_color(axis, hot == axis, tool_rings->edge_on(studio.camera(), axis)), 0, 2.0f);
  }
}

// ---- a stroke by numbers -------------------------------------------------------------------

bool SculptPanel::apply_stroke(Studio& studio) {
  if (!studio.document() || studio.selected_part() < 0) {
    studio.set_status("sculpt: select a part first", true);
    return false;
  }
  const scene::Part& part = studio.document()->scene().parts[studio.selected_part()];
  std::string problem;
  const std::optional<sculpt::Tool> tool = make_tool(studio, nullptr, nullptr, problem);
  const std::optional<sculpt::ToolMotion> motion = tool ? make_motion(settings_, problem) : std::nullopt;
  if (!motion) {
    studio.set_status("sculpt: " + problem, true);
    return false;
  }
  geometry::Mesh mesh = part.mesh;
  Eigen::MatrixX3d no_normals(0, 3);
  const sculpt::StrokeResult result = sculpt::sculpt_mesh({{*tool, *motion}}, stroke_options(settings_), mesh, no_normals);
  if (!result.applied) {
    studio.set_status(fmt::format("sculpt: {} refused the stroke: {}", part.name, result.refusal), true);
    return false;
  }
  const std::string name = part.name;  // `part` does not outlive the edit
  if (!studio.execute(scene::replace_part_mesh(name, std::move(mesh)))) return false;
  studio.set_status(fmt::format("sculpted {}: {} sub-steps, {} vertices moved, least det J {:.3g}", name,
                                result.substeps, result.vertices_moved, result.min_jacobian_determinant));
  return true;
}

// ---- sculpt mode ---------------------------------------------------------------------------

bool SculptPanel::set_mode(Studio& studio, bool on) {
  if (stroke_) finish_stroke(studio);
  placing_ = false;
  if (on && (!studio.document() || studio.selected_part() < 0)) {
    studio.set_status("sculpt mode: select a part first", true);
    on = false;
  }
  mode_ = on;
  if (on)
    studio.set_status(fmt::format("sculpt mode for {}: right-drag places the tool, left-drag sculpts (K leaves)",
                                  studio.document()->scene().parts[studio.selected_part()].name));
  return mode_;
}

std::optional<Eigen::Vector3d> SculptPanel::hit_part(const Studio& studio, const view::Ray& ray) const {
  const std::optional<Eigen::Isometry3d> to_world = part_to_world(studio);
  if (!to_world) return std::nullopt;
  const geometry::Mesh& mesh = studio.document()->scene().parts[studio.selected_part()].mesh;
  const Eigen::MatrixX3d V = (mesh.V * to_world->linear().transpose()).rowwise() + to_world->translation().transpose();
  const std::optional<view::MeshHit> hit = view::ray_mesh(ray, V, mesh.F);
  if (!hit) return std::nullopt;
  return ray.origin + hit->s * ray.direction;
}

void SculptPanel::place_tool(Studio& studio, const view::Ray& ray) {
  const std::optional<Eigen::Vector3d> hit = hit_part(studio, ray);
  const std::optional<Eigen::Isometry3d> to_world = part_to_world(studio);
  if (!hit || !to_world || settings_.shape == 4) return;  // a baked part stays where it is
  settings_.center = to_world->inverse() * *hit;
}

bool SculptPanel::start_stroke(Studio& studio, const view::Ray& ray, std::optional<int> ring) {
  const std::optional<Eigen::Isometry3d> to_world = part_to_world(studio);
  if (!to_world) return false;
  geometry::Mesh shape;
  Eigen::Vector3d origin;
  std::string problem;
  const std::optional<sculpt::Tool> tool = make_tool(studio, &shape, &origin, problem);
  if (!tool) {
    studio.set_status("sculpt: " + problem, true);
    return false;
  }
  const geometry::Mesh world_shape =
      mapped(shape, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(*to_world * tool->pose().to_world(p)); });
  const std::optional<ToolRings> tool_rings = ring ? rings(studio) : std::nullopt;
  if (!tool_rings && !hit_part(studio, ray) && !view::ray_mesh(ray, world_shape.V, world_shape.F)) return false;
  const scene::Part& part = studio.document()->scene().parts[studio.selected_part()];
  Stroke stroke{.part = part.name, .sculpted = sculpt::SculptMesh(part.mesh, Eigen::MatrixX3d(0, 3)), .tool = *tool};
  stroke.tool_origin = origin;
  stroke.to_world = *to_world;
  stroke.plane_normal = studio.camera().forward();
  const Eigen::Vector3d center = *to_world * tool->pose().to_world(origin);
  const std::optional<double> s = view::ray_plane(ray, center, stroke.plane_normal);
  stroke.last_point = s ? Eigen::Vector3d(ray.origin + *s * ray.direction) : center;
  if (tool_rings) {
    stroke.ring = ring;
    stroke.turn_axis = tool_rings->axes.col(*ring);
  } else if (drag_mode == DragMode::kTurn) {
    stroke.turn_axis = stroke.plane_normal;
  }
  stroke.last_mouse = {ImGui::GetIO().MousePos.x, ImGui::GetIO().MousePos.y};
  stroke_ = std::move(stroke);
  return true;
}

bool SculptPanel::move_tool(Studio& studio, const sculpt::ToolMotion& motion) {
  Stroke& s = *stroke_;
  const sculpt::StrokeResult result = sculpt::sculpt_mesh({{s.tool, motion}}, stroke_options(settings_), s.sculpted);
  if (!result.applied) {
    s.stopped = true;
    studio.set_status(fmt::format("sculpt: {} refused the move, the stroke stops at its last good state: {}", s.part,
                                  result.refusal),
                      true);
    return false;
  }
  s.tool = result.tools.front();
  s.moves += 1;
  s.substeps += result.substeps;
  s.vertices_moved += result.vertices_moved;
  s.least_determinant = std::min(s.least_determinant, result.min_jacobian_determinant);
  return result.vertices_moved > 0 || result.splits > 0 || result.collapses > 0;  // else no edit to show
}

void SculptPanel::continue_stroke(Studio& studio, const view::Ray& ray) {
  Stroke& s = *stroke_;
  if (s.stopped) return;
  const Eigen::Matrix3d to_rest = s.to_world.linear().transpose();
  bool moved = false;
  if (s.turn_axis) {
    moved = turn_tool(studio);
  } else if (const std::optional<double> t = view::ray_plane(ray, s.last_point, s.plane_normal)) {
    const Eigen::Vector3d point = ray.origin + *t * ray.direction;
    const Eigen::Vector3d d = to_rest * (point - s.last_point);
    s.last_point = point;
    if (d.norm() > 0) moved = move_tool(studio, sculpt::ToolMotion::translation(d));
  }
  const float wheel = ImGui::GetIO().MouseWheel;
  if (wheel != 0 && !s.stopped)
    moved = move_tool(studio, sculpt::ToolMotion::scaling(std::pow(kWheelScale, wheel), s.tool.pose().to_world(s.tool_origin))) ||
            moved;
  if (moved) show_live(studio);
}

bool SculptPanel::turn_tool(Studio& studio) {
  Stroke& s = *stroke_;
  const Eigen::Vector3d center_rest = s.tool.pose().to_world(s.tool_origin);
  const Eigen::Vector2d mouse(ImGui::GetIO().MousePos.x, ImGui::GetIO().MousePos.y);
  const std::optional<ImVec2> at = studio.viewport_point(s.to_world * center_rest);
  const double turn = at ? swept_turn({at->x, at->y}, s.last_mouse, mouse, *s.turn_axis, s.plane_normal) : 0;
  s.last_mouse = mouse;
  if (turn == 0) return false;
  const Eigen::Vector3d axis_rest = s.to_world.linear().transpose() * *s.turn_axis;
  return move_tool(studio, sculpt::ToolMotion::rotation(axis_rest, turn, center_rest));
}

void SculptPanel::show_live(Studio& studio) {
  Stroke& s = *stroke_;
  Document& document = *studio.document();
  if (s.live && document.version() == s.live_version) document.undo();
  s.live = studio.execute(scene::replace_part_mesh(s.part, s.sculpted.mesh()));
  s.live_version = document.version();
  if (s.stopped)  // the refusal stays in the status line
    studio.set_status(fmt::format("sculpt: {} refused a move; the stroke stopped at its last good state", s.part), true);
}

void SculptPanel::finish_stroke(Studio& studio) {
  const Stroke s = std::move(*stroke_);
  stroke_.reset();
  if (s.moves == 0) return;
  settings_.center = s.tool.pose().to_world(s.tool_origin);  // the next stroke starts where this one ended
  settings_.rotation = s.tool.pose().rotation.normalized();   // as turned
  if (settings_.shape != 4) settings_.size *= s.tool.pose().scale;
  if (!s.stopped)
    studio.set_status(fmt::format("sculpted {}: {} moves, {} sub-steps, {} vertex moves, least det J {:.3g}", s.part,
                                  s.moves, s.substeps, s.vertices_moved, s.least_determinant));
}

bool SculptPanel::handle_mouse(Studio& studio, const view::Ray& ray, bool hovered) {
  if (!mode_) return false;
  if (!studio.document() || studio.selected_part() < 0) {
    set_mode(studio, false);
    return false;
  }
  if (stroke_) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) continue_stroke(studio, ray);
    else finish_stroke(studio);
    return true;
  }
  if (placing_) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) place_tool(studio, ray);
    else placing_ = false;
    return true;
  }
  if (!hovered) return false;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) && hit_part(studio, ray)) {
    placing_ = true;
    place_tool(studio, ray);
    return true;
  }
  return ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
         start_stroke(studio, ray, ring_at(studio, ImGui::GetIO().MousePos));
}

// ---- the inspector's section ---------------------------------------------------------------

void SculptPanel::draw_mode_controls(Studio& studio) {
  bool on = mode_;
  if (ImGui::Checkbox("sculpt mode (K)", &on)) set_mode(studio, on);
  if (!mode_) return;
  ImGui::SameLine();
  int mode = static_cast<int>(drag_mode);
  ImGui::RadioButton("move", &mode, 0);
  ImGui::SameLine();
  ImGui::RadioButton("turn", &mode, 1);
  drag_mode = static_cast<DragMode>(mode);
  ImGui::TextDisabled("right-drag: place on the surface; left-drag: sculpt (on a ring: turn), wheel: scale");
}

void SculptPanel::draw_rotation_fields() {
  AxisAngle shown = axis_angle_of(settings_.rotation);
  ImGui::InputScalarN("tool axis", ImGuiDataType_Double, shown.axis.data(), 3, nullptr, nullptr, "%.3f");
  bool edited = ImGui::IsItemDeactivatedAfterEdit();
  ImGui::InputDouble("tool degrees", &shown.degrees, 0, 0, "%.2f");
  edited = ImGui::IsItemDeactivatedAfterEdit() || edited;
  if (const std::optional<Eigen::Quaterniond> q = edited ? rotation_of(shown) : std::nullopt) settings_.rotation = *q;
  ImGui::SameLine();
  if (ImGui::SmallButton("unturn")) settings_.rotation = Eigen::Quaterniond::Identity();
}

void SculptPanel::draw(Studio& studio) {
  if (!studio.document() || studio.selected_part() < 0) return;
  Settings& s = settings_;
  ImGui::Separator();
  if (!ImGui::CollapsingHeader("Sculpt")) return;
  draw_mode_controls(studio);
  const char* shapes[] = {"sphere", "box", "capsule", "ellipsoid", "a part"};
  ImGui::Combo("tool", &s.shape, shapes, 5);
  if (s.shape == 4) {
    const auto& parts = studio.document()->scene().parts;
    const char* current = s.tool_part >= 0 && s.tool_part < int(parts.size()) ? parts[s.tool_part].name.c_str() : "(pick)";
    if (ImGui::BeginCombo("tool part", current)) {
      for (int p = 0; p < int(parts.size()); ++p)
        if (p != studio.selected_part() && ImGui::Selectable(parts[p].name.c_str(), p == s.tool_part)) s.tool_part = p;
      ImGui::EndCombo();
    }
  } else {
    const char* size_label = s.shape == 0 ? "radius" : s.shape == 1 ? "edges" : s.shape == 2 ? "radius, length" : "semi-axes";
    ImGui::InputScalarN(size_label, ImGuiDataType_Double, s.size.data(), s.shape == 0 ? 1 : s.shape == 2 ? 2 : 3, nullptr,
                        nullptr, "%.4f");
  }
  ImGui::InputDouble("coating", &s.coating, 0, 0, "%.4f");
  if (s.shape != 4) {
    ImGui::InputScalarN("tool center", ImGuiDataType_Double, s.center.data(), 3, nullptr, nullptr, "%.4f");
    ImGui::SameLine();
    if (ImGui::SmallButton("part center"))
      s.center = geometry::bounding_box(studio.document()->scene().parts[studio.selected_part()].mesh.V).center();
  }
  if (s.shape != 0) draw_rotation_fields();
  int mirror = s.mirror + 1;
  const char* mirrors[] = {"no mirror", "mirror x = 0", "mirror y = 0", "mirror z = 0"};
  if (ImGui::Combo("mirror", &mirror, mirrors, 4)) s.mirror = mirror - 1;
  ImGui::InputDouble("remesh edge", &s.remesh, 0, 0, "%.4f");
  ImGui::Separator();
  const char* strokes[] = {"translate", "scale", "rotate"};
  ImGui::Combo("stroke", &s.stroke, strokes, 3);
  if (s.stroke == 0) ImGui::InputScalarN("by", ImGuiDataType_Double, s.translation.data(), 3, nullptr, nullptr, "%.4f");
  if (s.stroke == 1) ImGui::InputDouble("factor", &s.factor, 0, 0, "%.4f");
  if (s.stroke == 2) {
    ImGui::InputScalarN("axis", ImGuiDataType_Double, s.axis.data(), 3, nullptr, nullptr, "%.3f");
    ImGui::InputDouble("degrees", &s.degrees, 0, 0, "%.2f");
  }
  if (ImGui::Button("Apply stroke")) apply_stroke(studio);
  ImGui::TextDisabled("in the part's rest frame; each stroke is one undoable edit");
}

}  // namespace reconfig::studio
