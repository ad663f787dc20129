#include "shaping_panel.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>

#include "reconfig/geometry/bounding_box.h"
#include "reconfig/scene/edits.h"
#include "reconfig/sweep/relative_motion.h"
#include "reconfig/sweep/screw_envelope.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

/// The screws approximating `part`'s world motion over `transition`: one per time step in
/// which no point of it moves more than 1 % of its box's diagonal.
std::vector<motion::ScrewMotion> part_screws(const scene::Reconfigurable& scene, int transition, int part) {
  const sweep::RelativeMotion motion = sweep::relative_motion(scene, transition, part, -1);
  const double size = geometry::bounding_box(scene.parts[part].mesh.V).diagonal().norm();
  double reached = 0;
  const std::vector<double> times = motion.time_samples(std::max(0.01 * size, 1e-9), reached);
  std::vector<motion::ScrewMotion> screws;
  for (std::size_t k = 0; k + 1 < times.size(); ++k) screws.emplace_back(motion.at(times[k]), motion.at(times[k + 1]));
  if (screws.empty()) screws.emplace_back(motion.at(0), motion.at(1));
  return screws;
}

/// The parts that collide with `part` somewhere in `transition`, by the collision picture.
std::vector<std::string> colliding_parts(const Studio& studio, int transition, int part) {
  std::vector<std::string> names;
  const auto snapshot = studio.collisions();
  if (!snapshot) return names;
  const scene::Reconfigurable& scene = studio.document()->scene();
  for (const auto& t : snapshot->transitions) {
    if (t.transition != transition) continue;
    for (const auto& interval : t.intervals) {
      if (std::find(interval.parts.begin(), interval.parts.end(), part) == interval.parts.end()) continue;
      for (int other : interval.parts)
        if (other != part && other < int(scene.parts.size()) &&
            std::find(names.begin(), names.end(), scene.parts[other].name) == names.end())
          names.push_back(scene.parts[other].name);
    }
  }
  return names;
}

}  // namespace

bool ShapingPanel::start_carve(Studio& studio, const CarveSettings& settings) {
  const Document* document = studio.document();
  if (!document || studio.selected_part() < 0 || studio.active_transition() < 0) {
    studio.set_status("carve: select a part and open a transition first", true);
    return false;
  }
  if (job_) {
    studio.set_status("carve: a carve is already running", true);
    return false;
  }
  const std::shared_ptr<const scene::Reconfigurable> scene = document->shared_scene();
  sweep::CarveRequest request;
  request.transition = studio.active_transition();
  request.part = studio.selected_part();
  for (const std::string& name : settings.carvers) {
    const int carver = scene->find_part(name);
    if (carver < 0 || carver == request.part) {
      studio.set_status(carver < 0 ? fmt::format("carve: no part \"{}\"", name)
                                   : fmt::format("carve: {} cannot carve itself", name),
                        true);
      return false;
    }
    request.carvers.push_back(carver);
  }
  if (request.carvers.empty()) {
    studio.set_status("carve: choose the parts whose motion carves " + scene->parts[request.part].name, true);
    return false;
  }
  if (!(settings.offset >= 0) || !(settings.grid >= 0)) {
    studio.set_status("carve: the offset and the grid step must be >= 0", true);
    return false;
  }
  if (!(0 <= settings.from && settings.from < settings.to && settings.to <= 1)) {
    studio.set_status(fmt::format("carve: the time range [{}, {}] is not within [0, 1]", settings.from, settings.to), true);
    return false;
  }
  request.sweep.offset = settings.offset;
  request.sweep.grid_step = settings.grid;
  request.t0 = settings.from;
  request.t1 = settings.to;
  auto job = std::make_unique<CarveJob>();
  job->part = scene->parts[request.part].name;
  job->version = document->version();
  CarveJob* raw = job.get();
  request.progress = [raw](double fraction) {
    raw->progress = fraction;
    return !raw->cancel.load();
  };
  job->result = std::async(std::launch::async, [scene, request] { return sweep::carve_part(*scene, request); });
  job_ = std::move(job);
  studio.set_status(fmt::format("carving {} by {}…", job_->part, fmt::join(settings.carvers, ", ")));
  return true;
}

void ShapingPanel::cancel_carve(Studio& studio) {
  if (!job_) return;
  job_.reset();  // asks the carve to stop and waits for it
  studio.set_status("carve cancelled; nothing changed");
}

void ShapingPanel::finish_carve(Studio& studio, sweep::CarveResult result) {
  const std::string part = job_->part;
  const std::uint64_t version = job_->version;
  job_.reset();
  if (!studio.document() || result.cancelled) return;
  if (studio.document()->version() != version) {
    studio.set_status("carve dropped: the design changed while it ran (carve again)", true);
    return;
  }
  if (!result.ok()) {
    studio.set_status(fmt::format("carve of {} refused: {}", part, result.problem), true);
    return;
  }
  int samples = 0;
  for (const sweep::SweptVolumeResult& sweep : result.sweeps) samples += sweep.time_samples;
  const double before = result.volume_before, after = result.volume_after;
  if (studio.execute(scene::replace_part_mesh(part, std::move(result.mesh))))
    studio.set_status(fmt::format("carved {}: volume {:.4g} -> {:.4g} ({} time samples)", part, before, after, samples));
}

void ShapingPanel::show_carve_window(Studio& studio) {
  if (!studio.document() || studio.selected_part() < 0 || studio.active_transition() < 0) {
    studio.set_status("carve: select a part and open a transition first", true);
    return;
  }
  CarveSettings settings;
  settings.carvers = colliding_parts(studio, studio.active_transition(), studio.selected_part());
  carve_draft_ = settings;
  const auto& parts = studio.document()->scene().parts;
  carver_checks_.assign(parts.size(), 0);
  for (std::size_t p = 0; p < parts.size(); ++p)
    carver_checks_[p] = std::find(settings.carvers.begin(), settings.carvers.end(), parts[p].name) != settings.carvers.end();
}

bool ShapingPanel::set_carve_window(Studio& studio, const CarveSettings& settings) {
  if (!carve_draft_ || !studio.document()) {
    studio.set_status("carve: the Carve window is not open", true);
    return false;
  }
  const scene::Reconfigurable& scene = studio.document()->scene();
  std::vector<char> checks(scene.parts.size(), 0);
  for (const std::string& name : settings.carvers) {
    const int carver = scene.find_part(name);
    if (carver < 0) {
      studio.set_status(fmt::format("carve: no part \"{}\"", name), true);
      return false;
    }
    checks[std::size_t(carver)] = 1;
  }
  carver_checks_ = std::move(checks);
  carve_draft_ = settings;
  return true;
}

std::optional<CarvePreview::Key> ShapingPanel::preview_key(const Studio& studio) const {
  const Document* document = studio.document();
  if (!carve_draft_ || !document || studio.selected_part() < 0 || studio.active_transition() < 0) return std::nullopt;
  CarvePreview::Key key;
  key.version = document->version();
  key.transition = studio.active_transition();
  key.part = studio.selected_part();
  for (std::size_t p = 0; p < carver_checks_.size(); ++p)
    if (carver_checks_[p] && int(p) != key.part) key.carvers.push_back(int(p));
  key.offset = std::max(0.0, carve_draft_->offset);
  key.grid = std::max(0.0, carve_draft_->grid);
  key.from = carve_draft_->from;
  key.to = carve_draft_->to;
  if (!(0 <= key.from && key.from < key.to && key.to <= 1)) return std::nullopt;
  return key;
}

std::shared_ptr<const geometry::Mesh> ShapingPanel::carve_preview(const Studio& studio) const {
  const std::optional<CarvePreview::Key> key = preview_key(studio);
  if (!key || preview_.shown() != key) return nullptr;
  return preview_.mesh();
}

std::shared_ptr<const geometry::Mesh> ShapingPanel::envelope(const Studio& studio) {
  const Document* document = studio.document();
  if (!envelope_shown_ || !document || studio.selected_part() < 0 || studio.active_transition() < 0) return nullptr;
  const EnvelopeKey key{document->shared_scene().get(), studio.active_transition(), studio.selected_part()};
  if (envelope_key_ != key) {
    const scene::Reconfigurable& scene = document->scene();
    const sweep::EnvelopePart part(scene.parts[key.part].mesh);
    const std::vector<motion::ScrewMotion> screws = part_screws(scene, key.transition, key.part);
    envelope_ = std::make_shared<const geometry::Mesh>(sweep::screw_envelope(part, screws).mesh);
    envelope_key_ = key;
    envelope_scene_ = document->shared_scene();  // keeps the key's address from being reused
  }
  return envelope_;
}

void ShapingPanel::add_to_draw_list(const Studio& studio, render::DrawList& list) {
  add_preview_to_draw_list(studio, list);
  const std::shared_ptr<const geometry::Mesh> mesh = envelope(studio);
  if (!mesh || mesh->empty()) return;
  render::MeshItem item;
  item.V = mesh->V;
  item.F = mesh->F;
  item.color = {0.3f, 0.55f, 0.95f};
  item.opacity = 0.25f;
  list.meshes.push_back(std::move(item));
}

void ShapingPanel::add_preview_to_draw_list(const Studio& studio, render::DrawList& list) const {
  const std::shared_ptr<const geometry::Mesh> mesh = carve_preview(studio);
  if (!mesh || mesh->empty()) return;
  // Placed with the carved part where it is now.
  const scene::Reconfigurable& scene = studio.document()->scene();
  const int part = studio.selected_part();
  const Eigen::Isometry3d pose =
      scene.pose_at(studio.active_transition(), part, studio.time()).to_isometry(scene.parts[part].center);
  render::MeshItem item;
  item.V = ((pose.linear() * mesh->V.transpose()).colwise() + pose.translation()).transpose();
  item.F = mesh->F;
  item.color = {0.7f, 0.2f, 0.95f};  // violet: apart from the selection's orange
  item.opacity = 0.45f;
  list.meshes.push_back(std::move(item));
}

void ShapingPanel::update(Studio& studio) {
  if (job_ && job_->result.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
    finish_carve(studio, job_->result.get());
  // The Carve window's preview follows its settings and the design; gone with the window.
  preview_.update();
  const std::optional<CarvePreview::Key> key = preview_key(studio);
  if (!key || job_) {
    preview_.clear();
    preview_stopped_.reset();
  } else if (key != preview_stopped_) {
    preview_stopped_.reset();
    preview_.request(studio.document()->shared_scene(), *key);
  }
}

void ShapingPanel::draw_preview_status(const Studio& studio) {
  if (preview_.computing()) {
    ImGui::TextUnformatted("Preview: sweeping...");
    ImGui::ProgressBar(float(preview_.progress()), {-80, 0});
    ImGui::SameLine();
    if (ImGui::Button("Stop##preview")) {
      preview_stopped_ = preview_key(studio);
      preview_.clear();
    }
  } else if (const auto mesh = carve_preview(studio)) {
    ImGui::Text("Preview: the swept volume in violet (%d triangles)", int(mesh->face_count()));
  } else if (preview_stopped_) {
    ImGui::TextUnformatted("Preview stopped (change a setting to sweep again)");
  }
}

void ShapingPanel::draw_time_range(Studio& studio) {
  const std::vector<collision::CollisionInterval> intervals = part_intervals(studio);
  const auto& parts = studio.document()->scene().parts;
  const auto label = [&](const collision::CollisionInterval& interval) {
    std::vector<std::string> others;
    for (const int p : interval.parts)
      if (p != studio.selected_part() && p < int(parts.size())) others.push_back(parts[p].name);
    return fmt::format("t {:.3f}-{:.3f} with {}", interval.t0, interval.t1, fmt::join(others, ", "));
  };
  const bool whole = carve_draft_->from == 0 && carve_draft_->to == 1;
  const std::string shown = whole ? "the whole transition" : fmt::format("t {:.3f}-{:.3f}", carve_draft_->from, carve_draft_->to);
  if (!ImGui::BeginCombo("over", shown.c_str())) return;
  if (ImGui::Selectable("the whole transition", whole)) {
    carve_draft_->from = 0;
    carve_draft_->to = 1;
  }
  for (std::size_t i = 0; i < intervals.size(); ++i)
    if (ImGui::Selectable(fmt::format("{}##range{}", label(intervals[i]), i).c_str())) choose_interval(studio, intervals[i]);
  ImGui::EndCombo();
}

void ShapingPanel::choose_interval(Studio& studio, const collision::CollisionInterval& interval) {
  if (!carve_draft_) return;
  carve_draft_->from = interval.t0;
  carve_draft_->to = interval.t1;
  std::fill(carver_checks_.begin(), carver_checks_.end(), 0);
  carve_draft_->carvers.clear();
  const auto& parts = studio.document()->scene().parts;
  for (const int p : interval.parts)
    if (p != studio.selected_part() && p < int(carver_checks_.size())) {
      carver_checks_[std::size_t(p)] = 1;
      carve_draft_->carvers.push_back(parts[std::size_t(p)].name);
    }
}

std::vector<collision::CollisionInterval> ShapingPanel::part_intervals(const Studio& studio) const {
  std::vector<collision::CollisionInterval> intervals;
  const auto snapshot = studio.collisions();
  if (!snapshot) return intervals;
  for (const auto& t : snapshot->transitions)
    if (t.transition == studio.active_transition())
      for (const auto& interval : t.intervals)
        if (!interval.clearance && interval.t0 < interval.t1 &&
            std::find(interval.parts.begin(), interval.parts.end(), studio.selected_part()) != interval.parts.end())
          intervals.push_back(interval);
  return intervals;
}

void ShapingPanel::draw(Studio& studio) {
  if (job_) {
    ImGui::SetNextWindowSize({360, 0}, ImGuiCond_Appearing);
    if (ImGui::Begin("Carving", nullptr, ImGuiWindowFlags_NoCollapse)) {
      ImGui::Text("carving %s", job_->part.c_str());
      ImGui::ProgressBar(float(job_->progress.load()), {-1, 0});
      if (ImGui::Button("Cancel")) cancel_carve(studio);
    }
    ImGui::End();
  }
  if (!carve_draft_ || !studio.document()) return;
  const auto& parts = studio.document()->scene().parts;
  if (carver_checks_.size() != parts.size() || studio.selected_part() < 0) {
    carve_draft_.reset();
    return;
  }
  bool open = true;
  ImGui::SetNextWindowSize({380, 0}, ImGuiCond_Appearing);
  if (ImGui::Begin("Carve", &open, ImGuiWindowFlags_NoCollapse)) {
    ImGui::TextWrapped("Carve %s by the volume these parts sweep through it:", parts[studio.selected_part()].name.c_str());
    draw_time_range(studio);
    for (std::size_t p = 0; p < parts.size(); ++p) {
      if (int(p) == studio.selected_part()) continue;
      bool checked = carver_checks_[p];
      if (ImGui::Checkbox(parts[p].name.c_str(), &checked)) carver_checks_[p] = checked;
    }
    ImGui::InputDouble("offset", &carve_draft_->offset, 0, 0, "%.4f");
    ImGui::InputDouble("grid step (0: auto)", &carve_draft_->grid, 0, 0, "%.4f");
    draw_preview_status(studio);
    if (ImGui::Button("Carve") && !job_) {
      carve_draft_->carvers.clear();
      for (std::size_t p = 0; p < parts.size(); ++p)
        if (carver_checks_[p] && int(p) != studio.selected_part()) carve_draft_->carvers.push_back(parts[p].name);
      if (start_carve(studio, *carve_draft_)) open = false;
    }
    ImGui::SameLine();
    if (ImGui::Button("Close")) open = false;
  }
  ImGui::End();
  if (!open) carve_draft_.reset();
}

}  // namespace reconfig::studio
