#include "view_search.h"

#include "reconfig/render/best_view.h"
#include "reconfig/render/egl_context.h"
#include "reconfig/resolve/interval_energy.h"
#include "reconfig/view/scene_bounds.h"

namespace reconfig::studio {
namespace {

// The GL objects of the search thread, made at its first search, current on it only.
struct SearchContext {
  render::EglContext context;
  render::OcclusionCounter counter;
};

ViewSearch::Result search(SearchContext& gl, const ViewSearch::Request& request) {
  const scene::Reconfigurable& scene = *request.scene;
  resolve::ShapeCache shapes;  // a new design each time: shapes are not kept
  ViewSearch::Result result;
  result.time = resolve::interval_energy(scene, shapes, request.transition, request.interval).severity_time;
  render::BestViewRequest view = render::interval_view_request(scene, request.transition, request.interval, result.time);
  view.fov_y = request.fov_y;
  result.camera = render::best_view(gl.counter, scene, view).camera;
  result.camera.fit_planes(view::scene_bounds_at(scene, request.transition, result.time));  // the whole design
  return result;
}

}  // namespace

ViewSearch::ViewSearch() : thread_([this] { run(); }) {}

ViewSearch::~ViewSearch() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    waiting_.reset();
  }
  wake_.notify_all();
  thread_.join();
}

std::uint64_t ViewSearch::submit(Request request) {
  std::uint64_t id = 0;
  {
    std::lock_guard lock(mutex_);
    id = ++latest_;
    waiting_ = std::move(request);
    done_.reset();
  }
  wake_.notify_all();
  return id;
}

void ViewSearch::cancel() {
  std::lock_guard lock(mutex_);
  ++latest_;
  waiting_.reset();
  done_.reset();
}

std::optional<ViewSearch::Result> ViewSearch::take() {
  std::lock_guard lock(mutex_);
  std::optional<Result> result = std::move(done_);
  done_.reset();
  return result;
}

bool ViewSearch::busy() const {
  std::lock_guard lock(mutex_);
  return waiting_ || running_ || done_;
}

void ViewSearch::run() {
  std::unique_ptr<SearchContext> gl;
  std::string gl_error;
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || waiting_; });
    if (stopping_) break;
    const Request request = std::move(*waiting_);
    waiting_.reset();
    const std::uint64_t id = latest_;
    running_ = true;
    lock.unlock();
    Result result;
    if (!gl && gl_error.empty()) try {
        gl = std::make_unique<SearchContext>();
      } catch (const std::exception& error) {
        gl_error = error.what();
      }
    if (gl) {
      try {
        result = search(*gl, request);
      } catch (const std::exception& error) {
        result.error = error.what();
      }
    } else {
      result.error = gl_error;
    }
    result.id = id;
    lock.lock();
    running_ = false;
    if (id == latest_) done_ = std::move(result);
  }
  lock.unlock();
  gl.reset();  // its GL objects go while the context is current, on this thread
}

}  // namespace reconfig::studio
