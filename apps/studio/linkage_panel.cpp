// The linkage panel: draws a transition's linkage drive (or a linkage file opened alone) in 2D,
// turns its motor with the timeline, and edits it by LinkEdit as joints and curves are dragged.

#include "linkage_panel.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "panel_window.h"
#include "reconfig/linkage/curve_edit.h"
#include "reconfig/linkage/linkage_file.h"
#include "reconfig/scene/linkage_drive_edits.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

constexpr double kPi = std::numbers::pi;
double radians(double degrees) { return degrees * kPi / 180; }
double degrees(double radians) { return radians * 180 / kPi; }

constexpr float kJointRadius = 5, kPickJoint = 10, kPickCurve = 8;
constexpr ImU32 kLinkColor = IM_COL32(70, 80, 110, 255), kCrankColor = IM_COL32(40, 90, 200, 255);
constexpr ImU32 kProblemColor = IM_COL32(210, 30, 30, 255), kEnclosureColor = IM_COL32(40, 150, 90, 255);
constexpr ImU32 kCurveColors[] = {IM_COL32(230, 120, 20, 255), IM_COL32(150, 60, 190, 255), IM_COL32(20, 150, 160, 255)};

ImU32 curve_color(std::size_t point, int alpha = 255) {
  const ImU32 color = kCurveColors[point % std::size(kCurveColors)];
  return (color & ~IM_COL32_A_MASK) | (static_cast<ImU32>(alpha) << IM_COL32_A_SHIFT);
}

/// A scene command with another label ("drag joint U of walk" rather than "set the linkage drive").
class Labelled final : public scene::Command {
 public:
  Labelled(std::unique_ptr<scene::Command> command, std::string label)
      : command_(std::move(command)), label_(std::move(label)) {}
  scene::DirtySet apply(scene::Reconfigurable& scene) override { return command_->apply(scene); }
  scene::DirtySet revert(scene::Reconfigurable& scene) override { return command_->revert(scene); }
  std::string label() const override { return label_; }

 private:
  std::unique_ptr<scene::Command> command_;
  std::string label_;
};

/// The angles the fine curves are drawn at: a whole turn, or the rocking range just inside.
std::vector<double> drawn_angles(const LinkageEditor& editor, int count) {
  const linkage::MotionRange& range = editor.range();
  const double lower = range.full_rotation ? editor.initial_angle() : range.lower + 1e-4 * (range.upper - range.lower);
  const double upper = range.full_rotation ? lower + 2 * kPi : range.upper - 1e-4 * (range.upper - range.lower);
  std::vector<double> angles;
  for (int k = 0; k <= count; ++k) angles.push_back(lower + (upper - lower) * k / count);
  return angles;
}

float distance(ImVec2 a, ImVec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

bool is_linkage_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return false;
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json document = nlohmann::json::parse(text.str(), nullptr, false);
  return document.is_object() && document.value("format", nlohmann::json()) == "reconfig-linkage";
}

// ---- opening -----------------------------------------------------------------------------

bool LinkagePanel::open_drive(Studio& studio, int transition) {
  const Document* document = studio.document();
  if (!document || transition < 0 || transition >= static_cast<int>(document->scene().transitions.size())) {
    studio.set_status("linkage editor: no such transition", true);
    return false;
  }
  const scene::Transition& t = document->scene().transitions[transition];
  if (!t.linkage) {
    studio.set_status(fmt::format("linkage editor: transition {} has no linkage drive", t.name), true);
    return false;
  }
  studio.open_transition(transition);
  lone_file_.reset();
  undo_.clear();
  redo_.clear();
  shown_ = true;
  synced_transition_ = -1;
  sync(studio);
  return true;
}

bool LinkagePanel::open_file(Studio& studio, const std::filesystem::path& file) {
  LinkageEditor fresh;
  try {
    fresh.set_linkage(linkage::read_linkage(file));
  } catch (const std::exception& error) {
    studio.set_status(fmt::format("cannot open the linkage: {}", error.what()), true);
    return false;
  }
  editor_.motor_interval.reset();
  load(fresh.linkage());
  editor_.reset_choices();
  lone_file_ = file;
  shown_ = true;
  undo_.clear();
  redo_.clear();
  lone_modified_ = false;
  lone_angle_ = editor_.initial_angle();
  remember_opened();
  fit_view();
  const std::string problem = editor_.motion_problem();
  studio.set_status(fmt::format("opened the linkage {}{}", file.string(), problem.empty() ? "" : ": " + problem));
  return true;
}

void LinkagePanel::close_unless_unsaved(Studio& studio) {
  if (lone_modified_ && !discard_armed_) {
    discard_armed_ = true;
    studio.set_status("the linkage has unsaved edits: Save them, or press Close again to discard them", true);
    return;
  }
  close();
}

void LinkagePanel::close() {
  shown_ = false;
  discard_armed_ = false;
  lone_file_.reset();
  joint_drag_.reset();
  curve_drag_.reset();
}

void LinkagePanel::document_opened(Studio& studio) {
  close();
  undo_.clear();
  redo_.clear();
  synced_transition_ = -1;
  const int active = studio.active_transition();
  shown_ = active >= 0 && studio.document()->scene().transitions[active].linkage.has_value();
}

int LinkagePanel::transition(const Studio& studio) const {
  if (!shown_ || lone_file_ || !studio.document()) return -1;
  const int active = studio.active_transition();
  return active >= 0 && studio.document()->scene().transitions[active].linkage ? active : -1;
}

void LinkagePanel::sync(Studio& studio) {
  const int t = transition(studio);
  if (t < 0) return;
  const Document& document = *studio.document();
  if (t == synced_transition_ && document.version() == synced_version_) return;
  const scene::LinkageDrive& drive = *document.scene().transitions[t].linkage;
  editor_.motor_interval = std::pair{radians(drive.from), radians(drive.to)};
  const bool same = !editor_.empty() && t == synced_transition_ &&
                    editor_.linkage().joints.size() == drive.linkage.joints.size() &&
                    editor_.linkage().initial_positions() == drive.linkage.initial_positions();
  try {
    if (!same) load(drive.linkage);
  } catch (const std::exception& error) {
    studio.set_status(fmt::format("linkage editor: {}", error.what()), true);
    shown_ = false;
    return;
  }
  if (t != synced_transition_) {
    editor_.reset_choices();
    remember_opened();
    fit_view();
    if (const std::string problem = editor_.motion_problem(); !problem.empty())
      studio.set_status(fmt::format("{} — the linkage of {}: {}", studio.status(),
                                    document.scene().transitions[t].name, problem));
  }
  synced_transition_ = t;
  synced_version_ = document.version();
}

void LinkagePanel::load(linkage::Linkage linkage) {
  editor_.set_linkage(std::move(linkage));
  const linkage::MotionRange& range = editor_.range();
  if (!range.full_rotation) lone_angle_ = std::clamp(lone_angle_, range.lower, range.upper);
  drawn_curves_.assign(editor_.linkage().tracking_points.size(), {});
  Eigen::Matrix2Xd X;
  for (double angle : drawn_angles(editor_, 240)) {
    if (!editor_.solve(angle, X)) continue;
    for (std::size_t p = 0; p < drawn_curves_.size(); ++p)
      drawn_curves_[p].push_back(X.col(editor_.linkage().tracking_points[p].joint));
  }
}

void LinkagePanel::remember_opened() {
  opened_angles_ = editor_.sample_angles();
  opened_curves_.clear();
  for (std::size_t p = 0; p < editor_.linkage().tracking_points.size(); ++p) opened_curves_.push_back(editor_.curve(p));
}

void LinkagePanel::fit_view() {
  Eigen::AlignedBox2d box;
  Eigen::Matrix2Xd X;
  for (double angle : drawn_angles(editor_, 72))
    if (editor_.solve(angle, X))
      for (Eigen::Index j = 0; j < X.cols(); ++j) box.extend(X.col(j));
  if (box.isEmpty()) box.extend(editor_.linkage().initial_positions().rowwise().minCoeff()).extend(
      editor_.linkage().initial_positions().rowwise().maxCoeff());
  view_center_ = box.center();
  view_size_ = std::max(box.sizes().maxCoeff() * 1.15, 1e-9);
  soft_radius = 0.15 * box.sizes().norm();
}

// ---- geometry ----------------------------------------------------------------------------

double LinkagePanel::angle(const Studio& studio) const {
  const int t = transition(studio);
  if (t < 0) return lone_angle_;
  const scene::LinkageDrive& drive = *studio.document()->scene().transitions[t].linkage;
  return radians(drive.from + studio.time() * (drive.to - drive.from));
}

bool LinkagePanel::joints_now(const Studio& studio, Eigen::Matrix2Xd& X) const {
  return !editor_.empty() && editor_.solve(angle(studio), X);
}

ImVec2 LinkagePanel::screen_point(const Eigen::Vector2d& p) const {
  const float side = std::max(std::min(canvas_max_.x - canvas_min_.x, canvas_max_.y - canvas_min_.y), 1.0f);
  const double scale = side / view_size_;
  const ImVec2 center{(canvas_min_.x + canvas_max_.x) / 2, (canvas_min_.y + canvas_max_.y) / 2};
  return {static_cast<float>(center.x + scale * (p.x() - view_center_.x())),
          static_cast<float>(center.y - scale * (p.y() - view_center_.y()))};
}

Eigen::Vector2d LinkagePanel::linkage_point(ImVec2 s) const {
  const float side = std::max(std::min(canvas_max_.x - canvas_min_.x, canvas_max_.y - canvas_min_.y), 1.0f);
  const double scale = side / view_size_;
  const ImVec2 center{(canvas_min_.x + canvas_max_.x) / 2, (canvas_min_.y + canvas_max_.y) / 2};
  return {view_center_.x() + (s.x - center.x) / scale, view_center_.y() - (s.y - center.y) / scale};
}

// ---- edits -------------------------------------------------------------------------------

bool LinkagePanel::apply(Studio& studio, const LinkageEditOutcome& outcome, const std::string& label) {
  if (!outcome.refusal.empty()) {
    studio.set_status(fmt::format("{}: refused — {}", label, outcome.refusal), true);
    return false;
  }
  if (lone()) {
    undo_.push_back(editor_.linkage());
    redo_.clear();
    load(outcome.result.linkage);
    lone_modified_ = true;
    discard_armed_ = false;
  } else {
    const int t = transition(studio);
    if (t < 0) return false;
    const scene::Transition& transition = studio.document()->scene().transitions[t];
    scene::LinkageDrive drive = *transition.linkage;
    drive.linkage = outcome.result.linkage;
    drive.file.reset();  // the edited linkage is saved in the scene, the shared file stays as it is
    drive.compiled.clear();
    if (!studio.execute(std::make_unique<Labelled>(scene::set_linkage_drive(transition.name, std::move(drive)), label)))
      return false;
    sync(studio);
  }
  studio.set_status(fmt::format("{}: {}", label, outcome.summary));
  return true;
}

bool LinkagePanel::fit(Studio& studio) {
  const int t = transition(studio);
  return apply(studio, editor_.fit(),
               t >= 0 ? fmt::format("fit the linkage of {}", studio.document()->scene().transitions[t].name)
                      : std::string("fit the linkage"));
}

bool LinkagePanel::undo(Studio& studio) {
  if (undo_.empty()) {
    studio.set_status("nothing to undo");
    return false;
  }
  redo_.push_back(editor_.linkage());
  load(undo_.back());
  undo_.pop_back();
  lone_modified_ = true;
  discard_armed_ = false;
  studio.set_status("undid the linkage edit");
  return true;
}

bool LinkagePanel::redo(Studio& studio) {
  if (redo_.empty()) {
    studio.set_status("nothing to redo");
    return false;
  }
  undo_.push_back(editor_.linkage());
  load(redo_.back());
  redo_.pop_back();
  lone_modified_ = true;
  discard_armed_ = false;
  studio.set_status("redid the linkage edit");
  return true;
}

bool LinkagePanel::save(Studio& studio, const std::optional<std::filesystem::path>& file) {
  if (!lone()) return false;
  const std::filesystem::path target = file ? *file : *lone_file_;
  try {
    linkage::write_linkage(editor_.linkage(), target);
  } catch (const std::exception& error) {
    studio.set_status(fmt::format("not saved: {}", error.what()), true);
    return false;
  }
  lone_file_ = target;
  lone_modified_ = false;
  studio.set_status(fmt::format("saved {}", target.string()));
  return true;
}

// ---- drawing -----------------------------------------------------------------------------

void LinkagePanel::draw(Studio& studio) {
  sync(studio);
  draw_open_dialog(studio);
  if (!shown_ || editor_.empty() || (!lone() && transition(studio) < 0)) return;
  if (lone() && lone_playing_) {
    const linkage::MotionRange& range = editor_.range();
    lone_angle_ += ImGui::GetIO().DeltaTime * 2 * kPi / 4;  // a turn in 4 s
    if (!range.full_rotation && lone_angle_ > range.upper) lone_angle_ = range.lower;
  }
  const PanelRects rects = current_panel_rects();
  const ImVec2 size = lone() ? ImVec2{rects.viewport_size.x, rects.viewport_size.y + rects.timeline_size.y}
                             : ImVec2{std::max(rects.viewport_size.x * 0.45f, 300.0f), rects.viewport_size.y};
  ImGui::SetNextWindowPos(rects.viewport_pos);
  ImGui::SetNextWindowSize(size);
  if (ImGui::Begin("Linkage##panel", nullptr,
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar)) {
    draw_controls(studio);
    draw_canvas(studio, ImGui::GetContentRegionAvail());
  }
  ImGui::End();
}

void LinkagePanel::draw_controls(Studio& studio) {
  const linkage::Linkage& mechanism = editor_.linkage();
  const int t = transition(studio);
  if (t >= 0) {
    ImGui::Text("%s: linkage drive, %zu joints, %zu links", studio.document()->scene().transitions[t].name.c_str(),
                mechanism.joints.size(), mechanism.links.size());
    if (ImGui::Button(studio.playing() ? "Pause" : "Play")) studio.toggle_play();
    ImGui::SameLine();
    float time = static_cast<float>(studio.time());
    ImGui::SetNextItemWidth(140);
    if (ImGui::SliderFloat("t", &time, 0, 1, "%.3f")) studio.set_time(time);
    ImGui::SameLine();
    ImGui::Text("motor %.1f°", degrees(angle(studio)));
    ImGui::SameLine();
    if (ImGui::Button("Close")) close();
  } else {
    ImGui::Text("%s%s: %zu joints, %zu links", lone_file_->filename().string().c_str(), lone_modified_ ? " *" : "",
                mechanism.joints.size(), mechanism.links.size());
    if (ImGui::Button(lone_playing_ ? "Pause" : "Play")) lone_playing_ = !lone_playing_;
    ImGui::SameLine();
    const linkage::MotionRange& range = editor_.range();
    float shown = static_cast<float>(degrees(lone_angle_));
    ImGui::SetNextItemWidth(160);
    if (ImGui::SliderFloat("motor", &shown, static_cast<float>(degrees(range.lower)),
                           static_cast<float>(degrees(range.upper)), "%.1f°"))
      lone_angle_ = radians(shown);
    for (const char* label : {"Undo", "Redo", "Save", "Close"}) {
      ImGui::SameLine();
      if (!ImGui::Button(label)) continue;
      if (label[0] == 'U') undo(studio);
      else if (label[0] == 'R') redo(studio);
      else if (label[0] == 'S') save(studio);
      else close_unless_unsaved(studio);
    }
  }
  const std::string problem = editor_.motion_problem();
  if (problem.empty()) {
    ImGui::TextUnformatted(("motion: " + editor_.range().describe()).c_str());
  } else {
    const linkage::MotionRange& range = editor_.range();
    ImGui::TextColored({0.82f, 0.1f, 0.1f, 1}, "%s", problem.c_str());
    if (!range.full_rotation)
      ImGui::TextColored({0.82f, 0.1f, 0.1f, 1}, "dead point: %s", range.upper_failure.message.c_str());
  }
  for (std::size_t p = 0; p < mechanism.tracking_points.size(); ++p) {
    if (p > 0) ImGui::SameLine();
    bool keep = editor_.keep[p];
    if (ImGui::Checkbox(("keep " + mechanism.tracking_points[p].name).c_str(), &keep)) editor_.keep[p] = keep;
    if (editor_.targets[p]) {
      ImGui::SameLine();
      if (ImGui::SmallButton(("clear target##" + mechanism.tracking_points[p].name).c_str())) editor_.targets[p].reset();
    }
  }
  bool enclosed = editor_.enclosure.has_value();
  if (ImGui::Checkbox("enclosure", &enclosed)) {
    if (enclosed) {
      const Eigen::Vector2d half = Eigen::Vector2d::Constant(view_size_ / 2.3);
      editor_.enclosure = std::pair{view_center_ - half, view_center_ + half};
    } else {
      editor_.enclosure.reset();
    }
  }
  if (editor_.enclosure) {
    enclosure_draft_[0] = static_cast<float>(editor_.enclosure->first.x());
    enclosure_draft_[1] = static_cast<float>(editor_.enclosure->first.y());
    enclosure_draft_[2] = static_cast<float>(editor_.enclosure->second.x());
    enclosure_draft_[3] = static_cast<float>(editor_.enclosure->second.y());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(220);
    if (ImGui::InputFloat4("##box", enclosure_draft_, "%.1f") && enclosure_draft_[0] < enclosure_draft_[2] &&
        enclosure_draft_[1] < enclosure_draft_[3])
      editor_.enclosure = std::pair{Eigen::Vector2d(enclosure_draft_[0], enclosure_draft_[1]),
                                    Eigen::Vector2d(enclosure_draft_[2], enclosure_draft_[3])};
  }
  ImGui::SameLine();
  if (ImGui::Button("Fit")) fit(studio);
  float radius = static_cast<float>(soft_radius);
  ImGui::SetNextItemWidth(80);
  if (ImGui::DragFloat("curve radius", &radius, static_cast<float>(view_size_ / 200), 0.0f,
                       static_cast<float>(view_size_), "%.1f"))
    soft_radius = std::max(0.0f, radius);
  draw_transform_row(studio);
}

void LinkagePanel::draw_transform_row(Studio& studio) {
  const auto& points = editor_.linkage().tracking_points;
  if (points.empty()) return;
  transform_point_ = std::clamp(transform_point_, 0, static_cast<int>(points.size()) - 1);
  ImGui::SetNextItemWidth(70);
  if (ImGui::BeginCombo("##transform-point", points[transform_point_].name.c_str())) {
    for (int p = 0; p < static_cast<int>(points.size()); ++p)
      if (ImGui::Selectable(points[p].name.c_str(), p == transform_point_)) transform_point_ = p;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(190);
  ImGui::InputFloat4("##transform", transform_draft_, "%.2f");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("scale, turn (degrees), move x, move y of the target curve");
  ImGui::SameLine();
  if (!ImGui::Button("Transform")) return;
  if (!(transform_draft_[0] > 0)) {
    studio.set_status("transform the target: the scale must be > 0", true);
    return;
  }
  editor_.transform_target(transform_point_, transform_draft_[0], radians(transform_draft_[1]),
                           {transform_draft_[2], transform_draft_[3]});
  apply(studio, editor_.fit(), fmt::format("transform the curve of {}", points[transform_point_].name));
}

void LinkagePanel::draw_canvas(Studio& studio, ImVec2 size) {
  size = {std::max(size.x, 50.0f), std::max(size.y, 50.0f)};
  canvas_min_ = ImGui::GetCursorScreenPos();
  canvas_max_ = {canvas_min_.x + size.x, canvas_min_.y + size.y};
  ImGui::InvisibleButton("##linkage-canvas", size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(canvas_min_, canvas_max_, true);
  draw->AddRectFilled(canvas_min_, canvas_max_, IM_COL32(250, 250, 246, 255));
  Eigen::Matrix2Xd X;
  const bool solved = joints_now(studio, X);
  handle_mouse(studio, X);
  if (editor_.enclosure)
    draw->AddRect(screen_point({editor_.enclosure->first.x(), editor_.enclosure->second.y()}),
                  screen_point({editor_.enclosure->second.x(), editor_.enclosure->first.y()}), kEnclosureColor, 0, 0, 2);
  draw_curves(draw);
  if (solved) {
    draw_crank_range(draw, X);
    const bool previewing = joint_drag_ && joint_drag_->preview;
    draw_linkage(draw, editor_.linkage(), X, previewing ? IM_COL32(150, 150, 160, 140) : kLinkColor, !previewing);
  } else {
    draw->AddText({canvas_min_.x + 10, canvas_max_.y - 24}, kProblemColor, "the linkage cannot be assembled at this motor angle");
  }
  if (joint_drag_ && joint_drag_->preview) {
    Eigen::Matrix2Xd Y;
    const LinkageEditOutcome& preview = *joint_drag_->preview;
    const bool refused = !preview.refusal.empty();
    if (linkage::SymbolicKinematics(preview.result.linkage, linkage::order_joints(preview.result.linkage))
            .solve(joint_drag_->angle, Y))
      draw_linkage(draw, preview.result.linkage, Y, refused ? kProblemColor : IM_COL32(20, 140, 60, 255), true);
    const ImVec2 target = screen_point(joint_drag_->target);
    draw->AddCircle(target, 7, IM_COL32(200, 150, 0, 255), 12, 2);
    if (Y.cols() > joint_drag_->joint) draw->AddLine(screen_point(Y.col(joint_drag_->joint)), target, IM_COL32(200, 150, 0, 200));
    draw->AddText({canvas_min_.x + 10, canvas_max_.y - 24}, refused ? kProblemColor : IM_COL32(30, 90, 40, 255),
                  (refused ? preview.refusal : preview.summary).c_str());
  }
  draw->PopClipRect();
}

void LinkagePanel::handle_mouse(Studio& studio, const Eigen::Matrix2Xd& X) {
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  if (ImGui::IsItemActivated() && X.cols() == static_cast<Eigen::Index>(editor_.linkage().joints.size())) {
    int best = -1;
    float nearest = kPickJoint;
    for (Eigen::Index j = 0; j < X.cols(); ++j)
      if (const float d = distance(screen_point(X.col(j)), mouse); d < nearest) {
        nearest = d;
        best = static_cast<int>(j);
      }
    if (best >= 0) {
      joint_drag_ = JointDrag{best, angle(studio), X.col(best), X.col(best), mouse, std::nullopt};
    } else {
      nearest = kPickCurve;
      for (std::size_t p = 0; p < editor_.linkage().tracking_points.size(); ++p) {
        const auto& curve = editor_.targets[p] ? *editor_.targets[p] : editor_.curve(p);
        for (std::size_t s = 0; s < curve.size(); ++s)
          if (const float d = distance(screen_point(curve[s]), mouse); d < nearest) {
            nearest = d;
            curve_drag_ = CurveDrag{static_cast<int>(p), static_cast<int>(s), mouse, curve};
          }
      }
    }
  }
  if (joint_drag_) {
    const Eigen::Vector2d target = joint_drag_->start + linkage_point(mouse) - linkage_point(joint_drag_->press);
    if (target != joint_drag_->target || !joint_drag_->preview) {
      joint_drag_->target = target;
      joint_drag_->preview = editor_.drag_joint(joint_drag_->joint, target, joint_drag_->angle);
    }
    if (!ImGui::IsItemActive()) finish_joint_drag(studio);
  } else if (curve_drag_) {
    const Eigen::Vector2d displacement = linkage_point(mouse) - linkage_point(curve_drag_->press);
    editor_.targets[curve_drag_->point] = linkage::soft_drag_curve(curve_drag_->base, curve_drag_->index, displacement,
                                                                   soft_radius, editor_.range().full_rotation);
    if (!ImGui::IsItemActive()) finish_curve_drag(studio);
  }
}

void LinkagePanel::finish_joint_drag(Studio& studio) {
  const JointDrag drag = *joint_drag_;
  joint_drag_.reset();
  if (drag.target == drag.start) return;  // a click
  last_drag_ = std::pair{drag.joint, drag.target};
  const int t = transition(studio);
  const std::string label = fmt::format("drag joint {}{}", editor_.linkage().joints[drag.joint].name,
                                        t >= 0 ? " of " + studio.document()->scene().transitions[t].name : "");
  apply(studio, *drag.preview, label);
}

void LinkagePanel::finish_curve_drag(Studio& studio) {
  const CurveDrag drag = *curve_drag_;
  curve_drag_.reset();
  if (editor_.targets[drag.point] == drag.base) return;  // a click
  const std::string& name = editor_.linkage().tracking_points[drag.point].name;
  apply(studio, editor_.fit(), fmt::format("bend the curve of {}", name));
}

void LinkagePanel::draw_linkage(ImDrawList* draw, const linkage::Linkage& mechanism, const Eigen::Matrix2Xd& X,
                                ImU32 color, bool joints) const {
  const int center = mechanism.motor.center, crank = mechanism.motor.joint;
  for (const auto& link : mechanism.links) {
    const bool is_crank = std::find(link.begin(), link.end(), center) != link.end() &&
                          std::find(link.begin(), link.end(), crank) != link.end();
    std::vector<ImVec2> points;
    for (int j : link) points.push_back(screen_point(X.col(j)));
    if (points.size() == 3) draw->AddTriangleFilled(points[0], points[1], points[2], (color & ~IM_COL32_A_MASK) | IM_COL32(0, 0, 0, 40));
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), is_crank && joints ? kCrankColor : color,
                      points.size() > 2 ? ImDrawFlags_Closed : ImDrawFlags_None, 3);
  }
  if (!joints) return;
  const int dead = editor_.dead_point_joint();
  const bool enclosed = editor_.enclosure.has_value();
  for (Eigen::Index j = 0; j < X.cols(); ++j) {
    const ImVec2 p = screen_point(X.col(j));
    const bool outside = enclosed && (X.col(j).array() < editor_.enclosure->first.array() ||
                                      X.col(j).array() > editor_.enclosure->second.array()).any();
    const ImU32 outline = j == dead || outside ? kProblemColor : color;
    if (mechanism.joints[j].fixed)
      draw->AddRectFilled({p.x - kJointRadius, p.y - kJointRadius}, {p.x + kJointRadius, p.y + kJointRadius}, outline);
    else {
      draw->AddCircleFilled(p, kJointRadius, IM_COL32_WHITE, 16);
      draw->AddCircle(p, kJointRadius, outline, 16, 2);
    }
    draw->AddText({p.x + 7, p.y - 16}, IM_COL32(40, 40, 50, 255), mechanism.joints[j].name.c_str());
  }
}

void LinkagePanel::draw_crank_range(ImDrawList* draw, const Eigen::Matrix2Xd& X) const {
  const linkage::Linkage& mechanism = editor_.linkage();
  const ImVec2 center = screen_point(X.col(mechanism.motor.center));
  const float radius = distance(center, screen_point(X.col(mechanism.motor.joint)));
  const linkage::MotionRange& range = editor_.range();
  if (range.full_rotation) {
    draw->AddCircle(center, radius, IM_COL32(40, 150, 90, 160), 48, 1.5f);
    return;
  }
  // Screen y points down: a counterclockwise angle a is at −a on screen.
  draw->PathArcTo(center, radius, static_cast<float>(-range.upper), static_cast<float>(-range.lower), 48);
  draw->PathStroke(IM_COL32(40, 150, 90, 200), ImDrawFlags_None, 2);
  draw->PathArcTo(center, radius, static_cast<float>(-range.lower - 2 * kPi), static_cast<float>(-range.upper), 48);
  draw->PathStroke(kProblemColor, ImDrawFlags_None, 2);
}

void LinkagePanel::draw_curves(ImDrawList* draw) const {
  for (std::size_t p = 0; p < drawn_curves_.size(); ++p) {
    std::vector<ImVec2> points;
    for (const Eigen::Vector2d& q : drawn_curves_[p]) points.push_back(screen_point(q));
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), curve_color(p), ImDrawFlags_None, 2);
    if (!editor_.targets[p]) continue;
    const auto& target = *editor_.targets[p];
    for (std::size_t s = 0; s + 1 < target.size(); s += 2)  // dashed
      draw->AddLine(screen_point(target[s]), screen_point(target[s + 1]), curve_color(p, 200), 2);
    for (const Eigen::Vector2d& q : target) draw->AddCircleFilled(screen_point(q), 2.5f, curve_color(p, 200), 8);
  }
}

void LinkagePanel::request_open_dialog() { show_open_dialog_ = true; }

void LinkagePanel::draw_open_dialog(Studio& studio) {
  if (show_open_dialog_) ImGui::OpenPopup("Open linkage");
  show_open_dialog_ = false;
  if (!ImGui::BeginPopupModal("Open linkage", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%s", open_path_.c_str());
  ImGui::SetNextItemWidth(480);
  const bool entered = ImGui::InputText("##linkage-path", buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  open_path_ = buffer;
  if (entered || ImGui::Button("OK")) {
    open_file(studio, open_path_);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace reconfig::studio
