#include "carve_preview.h"

#include <chrono>

#include "reconfig/sweep/carve_part.h"

namespace reconfig::studio {
namespace {

/// The carvers' sweeps in the part's frame as one mesh (their shells side by side), or none
/// when cancelled.
std::optional<geometry::Mesh> swept_volumes(const scene::Reconfigurable& scene, const CarvePreview::Key& key,
                                            ProgressCallback progress) {
  sweep::CarveRequest request;
  request.transition = key.transition;
  request.part = key.part;
  request.carvers = key.carvers;
  request.sweep.offset = key.offset;
  request.sweep.grid_step = key.grid;
  request.t0 = key.from;
  request.t1 = key.to;
  request.progress = std::move(progress);
  geometry::Mesh all;
  for (const sweep::SweptVolumeResult& sweep : sweep::carver_sweeps(scene, request)) {
    if (sweep.cancelled) return std::nullopt;
    const Eigen::Index v0 = all.V.rows(), f0 = all.F.rows();
    all.V.conservativeResize(v0 + sweep.mesh.V.rows(), 3);
    all.F.conservativeResize(f0 + sweep.mesh.F.rows(), 3);
    all.V.bottomRows(sweep.mesh.V.rows()) = sweep.mesh.V;
    all.F.bottomRows(sweep.mesh.F.rows()) = sweep.mesh.F.array() + int(v0);
  }
  return all;
}

}  // namespace

void CarvePreview::request(std::shared_ptr<const scene::Reconfigurable> scene, const Key& key) {
  if (job_ && job_->key == key) return;
  job_.reset();  // a job for another key: cancelled (its thread ends first)
  if (shown_ == key) return;
  if (key.carvers.empty() || key.part < 0 || key.transition < 0) {
    clear();
    return;
  }
  auto job = std::make_unique<Job>();
  job->key = key;
  Job* raw = job.get();
  ProgressCallback progress = [raw](double fraction) {
    raw->progress = fraction;
    return !raw->cancel.load();
  };
  job->result = std::async(std::launch::async, [scene = std::move(scene), key, progress] {
    return swept_volumes(*scene, key, progress);
  });
  job_ = std::move(job);
}

void CarvePreview::update() {
  if (!job_ || job_->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  std::optional<geometry::Mesh> mesh = job_->result.get();
  const Key key = job_->key;
  job_.reset();
  if (!mesh) return;
  mesh_ = std::make_shared<const geometry::Mesh>(std::move(*mesh));
  shown_ = key;
  ++revision_;
}

void CarvePreview::clear() {
  job_.reset();
  if (mesh_ || shown_) ++revision_;
  mesh_.reset();
  shown_.reset();
}

}  // namespace reconfig::studio
