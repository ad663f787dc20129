#include "reconfig/collision/detect_collisions.h"

#include <algorithm>

#include "reconfig/collision/consolidate.h"
#include "reconfig/collision/tolerance_scale.h"
#include "reconfig/common/input_error.h"

namespace reconfig::collision {

bool CollisionResult::any_collision() const {
  return std::any_of(transitions.begin(), transitions.end(),
                     [](const TransitionCollisions& t) { return !t.intervals.empty(); });
}

CollisionResult detect_collisions(const scene::Reconfigurable& scene, const CollisionRequest& request) {
  std::vector<int> transitions = request.transitions;
  if (transitions.empty())
    for (int i = 0; i < static_cast<int>(scene.transitions.size()); ++i) transitions.push_back(i);
  if (const std::string problem = tolerance_scale_problem(scene, transitions, request.detector.tolerance);
      !problem.empty())
    throw InputError("", "collision.tolerance", problem);
  CollisionResult result;
  const BodyTrees trees = build_body_trees(scene);
  for (std::size_t i = 0; i < transitions.size(); ++i) {
    SpacetimeDetector detector(transitions[i], request.detector);
    DetectCallbacks callbacks;
    if (request.progress)
      callbacks.progress = [&](double f) { return request.progress((static_cast<double>(i) + f) / transitions.size()); };
    if (!detector.detect(scene, trees, callbacks)) {
      result.cancelled = true;
      return result;
    }
    const std::string& name = scene.transitions[transitions[i]].name;
    result.transitions.push_back({transitions[i], name, consolidate(detector.intervals(), detector.containments())});
    result.frames.push_back(
        {transitions[i], name, consolidate(detector.intervals(), detector.containments(), request.detector.frame)});
    result.stats += detector.last_stats();
  }
  return result;
}

}  // namespace reconfig::collision
