#include "reconfig/collision/reference_check.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <map>
#include <tuple>

#include "collision/detail/deep_inside.h"
#include "reconfig/collision/contact_tolerance.h"
#include "reconfig/collision/triangle_clearance.h"
#include "reconfig/collision/triangle_touching.h"
#include "reconfig/geometry/triangle_bvh.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::collision {
namespace {

using geometry::Mesh;
using geometry::TriangleBvh;

Eigen::Vector3d corner(const TriangleBvh& bvh, int f, int k) { return bvh.vertices().row(bvh.faces()(f, k)); }

/// How a sample tells a collision: the contact tolerance, and whether touching counts.
struct Semantics {
  double contact = 0;
  bool touching_collides = false;
  bool detect_containment = true;
  double clearance = 0;
};

/// Whether two posed parts come closer than `clearance` anywhere: every pair of triangles whose
/// boxes come that close, by their distance; `box` receives the boxes of those closer.
bool closer_than(const TriangleBvh& a, const TriangleBvh& b, double clearance, Eigen::AlignedBox3d& box) {
  bool closer = false;
  for (int f = 0; f < static_cast<int>(a.faces().rows()); ++f) {
    const TriangleCorners ta{corner(a, f, 0), corner(a, f, 1), corner(a, f, 2)};
    Eigen::AlignedBox3d reach;
    for (const Eigen::Vector3d& p : ta) reach.extend(p);
    const Eigen::AlignedBox3d own = reach;
    reach.min().array() -= clearance;
    reach.max().array() += clearance;
    b.for_each_overlapping(reach, [&](int g) {
      const TriangleCorners tb{corner(b, g, 0), corner(b, g, 1), corner(b, g, 2)};
      if (geometry::triangle_distance(ta, tb) >= clearance) return;
      closer = true;
      box.extend(own);
      for (const Eigen::Vector3d& p : tb) box.extend(p);
    });
  }
  return closer;
}

/// Exact contacts between two posed parts at one instant: intersecting triangle pairs that
/// interfere beyond δ (or every one, when touching collides).
void collide_pair(const TriangleBvh& a, const TriangleBvh& b, const Semantics& semantics, SampleContact& contact) {
  a.for_each_overlapping_pair(b, [&](int f, int g) {
    const TriangleCorners ta{corner(a, f, 0), corner(a, f, 1), corner(a, f, 2)};
    const TriangleCorners tb{corner(b, g, 0), corner(b, g, 1), corner(b, g, 2)};
    // (The cheap touching test first: it spares the exact intersection of touching faces.)
    if (!semantics.touching_collides && triangles_touch(ta, tb, semantics.contact)) return;
    const geometry::TriangleContact hit = geometry::intersect_triangles(ta[0], ta[1], ta[2], tb[0], tb[1], tb[2]);
    if (!hit.intersect) return;
    ++contact.triangle_pairs;
    for (const Eigen::Vector3d& p : hit.points) contact.box.extend(p);
  });
}

/// Whether posed part `inner` lies inside posed part `outer`, given that their surfaces do not
/// interfere: then one vertex not within δ of `outer`'s surface decides for the whole part.
bool inside(const TriangleBvh& inner, const TriangleBvh& outer, double delta) {
  if (!outer.bounds().contains(inner.bounds())) return false;
  const Mesh mesh{outer.vertices(), outer.faces()};
  return detail::lies_inside(mesh, inner.vertices(), inner.faces()(0, 0), delta);
}

/// Every colliding pair of parts at sample `sample` of `transition`.
std::vector<SampleContact> check_sample(const scene::Reconfigurable& scene, int transition, int sample,
                                        double t, const Semantics& semantics) {
  const int n = static_cast<int>(scene.parts.size());
  std::vector<TriangleBvh> posed;
  posed.reserve(n);
  for (int p = 0; p < n; ++p) posed.emplace_back(scene.posed_vertices(transition, p, t), scene.parts[p].mesh.F);
  std::vector<SampleContact> contacts;
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      Eigen::AlignedBox3d reach = posed[a].bounds();
      reach.min().array() -= semantics.clearance;
      reach.max().array() += semantics.clearance;
      if (!reach.intersects(posed[b].bounds())) continue;
      SampleContact contact{sample, a, b, {}, false, 0};
      collide_pair(posed[a], posed[b], semantics, contact);
      if (contact.triangle_pairs == 0 && semantics.detect_containment) {
        if (inside(posed[a], posed[b], semantics.contact)) {
          contact.containment = true;
          contact.box = posed[a].bounds();
        } else if (inside(posed[b], posed[a], semantics.contact)) {
          contact.containment = true;
          contact.box = posed[b].bounds();
        }
      }
      if (contact.triangle_pairs == 0 && !contact.containment && semantics.clearance > 0)
        contact.clearance = closer_than(posed[a], posed[b], semantics.clearance, contact.box);
      if (contact.triangle_pairs > 0 || contact.containment || contact.clearance) contacts.push_back(contact);
    }
  }
  return contacts;
}

/// Merges consecutive colliding samples of the same pair of parts into intervals (and
/// consecutive clearance samples into clearance intervals).
std::vector<CollisionInterval> merge_samples(const std::vector<SampleContact>& contacts, int samples) {
  std::map<std::tuple<int, int, bool>, std::vector<const SampleContact*>> by_pair;
  for (const SampleContact& c : contacts) by_pair[{c.part_a, c.part_b, c.clearance}].push_back(&c);
  std::vector<CollisionInterval> intervals;
  for (const auto& [key, list] : by_pair) {
    const auto [part_a, part_b, clearance] = key;
    CollisionInterval current;
    int last = -2;
    for (const SampleContact* c : list) {  // ascending sample order
      if (c->sample != last + 1) {
        if (last >= 0) intervals.push_back(current);
        current = CollisionInterval{sample_time(c->sample, samples), 0, {part_a, part_b}, {}, false, false, {}, clearance};
      }
      current.t1 = sample_time(c->sample, samples);
      current.box.extend(c->box);
      current.containment = current.containment || c->containment;
      last = c->sample;
    }
    if (last >= 0) intervals.push_back(current);
  }
  std::sort(intervals.begin(), intervals.end(), [](const CollisionInterval& x, const CollisionInterval& y) {
    return std::tie(x.t0, x.parts) < std::tie(y.t0, y.parts);
  });
  return intervals;
}

}  // namespace

bool ReferenceCheckResult::any_collision() const {
  return std::any_of(transitions.begin(), transitions.end(),
                     [](const TransitionCollisions& t) { return !t.intervals.empty(); });
}

ReferenceCheckResult reference_check(const scene::Reconfigurable& scene, const ReferenceCheckRequest& request) {
  assert(request.samples >= 2);
  std::vector<int> transitions = request.transitions;
  if (transitions.empty())
    for (int i = 0; i < static_cast<int>(scene.transitions.size()); ++i) transitions.push_back(i);

  ReferenceCheckResult result;
  result.samples = request.samples;
  result.time_error = 1.0 / (request.samples - 1);
  const Semantics semantics{contact_tolerance(scene, request.contact), request.touching_collides,
                            request.detect_containment, request.clearance};
  result.contact = semantics.contact;
  const double total = static_cast<double>(transitions.size()) * request.samples;
  std::atomic<long> done{0};
  std::atomic<bool> cancelled{false};
  for (int transition : transitions) {
    std::vector<std::vector<SampleContact>> per_sample(request.samples);
    tbb::parallel_for(tbb::blocked_range<int>(0, request.samples, 8), [&](const tbb::blocked_range<int>& range) {
      for (int i = range.begin(); i < range.end() && !cancelled; ++i) {
        per_sample[i] = check_sample(scene, transition, i, sample_time(i, request.samples), semantics);
        const long finished = ++done;
        // Only the first thread to see a cancel request records it; progress is best effort.
        if (request.progress && (finished % 16 == 0 || finished == total) &&
            !report_progress(request.progress, finished / total))
          cancelled = true;
      }
    });
    if (cancelled) {
      result.cancelled = true;
      break;
    }
    std::vector<SampleContact> contacts;
    for (auto& list : per_sample) contacts.insert(contacts.end(), list.begin(), list.end());
    TransitionCollisions collisions{transition, scene.transitions[transition].name,
                                    merge_samples(contacts, request.samples)};
    result.transitions.push_back(std::move(collisions));
    result.contacts.push_back(std::move(contacts));
  }
  return result;
}

}  // namespace reconfig::collision
