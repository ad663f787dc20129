#pragma once
/// @file
/// Best views of collision intervals (render/best_view.h) searched on a thread of its own, with
/// a headless OpenGL context of its own, so that the UI never waits for one. One search at a
/// time matters: a new request replaces the one waiting, and the one running, when it ends,
/// delivers nothing (it is stale). The UI polls `take` each frame.

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/view/camera.h"

namespace reconfig::studio {

class ViewSearch {
 public:
  struct Request {
    std::shared_ptr<const scene::Reconfigurable> scene;  ///< the design, validated
    int transition = 0;
    collision::CollisionInterval interval;  ///< of that transition of `scene`
    double fov_y = view::Camera{}.fov_y;
  };
  struct Result {
    std::uint64_t id = 0;      ///< that `submit` gave the request
    double time = 0;           ///< the interval's severity time
    view::Camera camera;       ///< its best view at that time, planes around the whole design
    std::string error;         ///< not empty: no view (no OpenGL context on the thread), `camera` unset
  };

  ViewSearch();
  /// Waits for the search running, if any, to end.
  ~ViewSearch();
  ViewSearch(const ViewSearch&) = delete;
  ViewSearch& operator=(const ViewSearch&) = delete;

  /// Asks for a search; the result of any earlier request will not be delivered. Returns its id.
  std::uint64_t submit(Request request);
  /// No result of the requests so far will be delivered.
  void cancel();
  /// The result of the latest request, once, when it is done.
  std::optional<Result> take();
  /// A request is waiting, running or done but not taken.
  bool busy() const;

 private:
  void run();

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Request> waiting_;
  std::uint64_t latest_ = 0;  ///< the id of the latest request; only its result is kept
  std::optional<Result> done_;
  bool running_ = false, stopping_ = false;
  std::thread thread_;
};

}  // namespace reconfig::studio
