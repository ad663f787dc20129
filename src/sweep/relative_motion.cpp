#include "reconfig/sweep/relative_motion.h"

#include <cassert>
#include <memory>
#include <utility>

#include "reconfig/motion/motion_bounds.h"

namespace reconfig::sweep {
namespace {

/// One part's motion in a transition: its rigid map at t, and (radius, a, b) ↦ the
/// displacement bound of points within `radius` of its center over [a, b] (0 when it holds).
struct PartMotion {
  std::function<Eigen::Isometry3d(double)> map;
  std::function<double(double, double, double)> displacement;
};

PartMotion part_motion(const scene::Reconfigurable& scene, int transition, int part) {
  const scene::Part& p = scene.parts[part];
  const scene::Transition& tr = scene.transitions[transition];
  const motion::Pose hold = scene.states[scene.find_state(tr.from)].pose_of(p.name);
  const Eigen::Vector3d center = p.center;
  const auto it = tr.tracks.find(p.name);
  if (it == tr.tracks.end()) {
    const Eigen::Isometry3d fixed = hold.to_isometry(center);
    return {[fixed](double) { return fixed; }, [](double, double, double) { return 0.0; }};
  }
  const auto map = [&scene, transition, part, center](double t) {
    return scene.pose_at(transition, part, t).to_isometry(center);
  };
  if (const auto* screw = std::get_if<scene::ScrewPosesTrack>(&it->second)) {
    auto track = std::make_shared<motion::ScrewTrack>(screw->poses, center);
    return {map, [track](double radius, double a, double b) {
              return motion::screw_motion_bound(*track, radius, a, b).displacement;
            }};
  }
  const auto& keyed = std::get<scene::KeyframedTrack>(it->second);
  const Eigen::Vector3d x = hold.translation;
  auto translation = std::make_shared<motion::BezierTranslationTrack>(
      keyed.translation.empty() ? std::vector<motion::TranslationKey>{{0.0, x, x, x}} : keyed.translation);
  auto rotation = std::make_shared<motion::SlerpRotationTrack>(
      keyed.rotation.empty() ? std::vector<motion::RotationKey>{{0.0, hold.rotation}} : keyed.rotation);
  return {map, [translation, rotation](double radius, double a, double b) {
            return motion::keyframed_motion_bound(*translation, *rotation, radius, a, b).displacement;
          }};
}

double part_radius(const scene::Part& part) {
  if (part.mesh.V.rows() == 0) return 0;
  return (part.mesh.V.rowwise() - part.center.transpose()).rowwise().norm().maxCoeff();
}

}  // namespace

RelativeMotion::RelativeMotion(PoseFunction pose, DisplacementBound displacement, double t0, double t1)
    : pose_(std::move(pose)), displacement_(std::move(displacement)), t0_(t0), t1_(t1) {
  assert(t0 <= t1);
}

std::vector<double> RelativeMotion::time_samples(double tolerance, double& reached, double min_step) const {
  // Each step as long as its own bound allows (to 2⁻²⁰ of the rest of the range), not only
  // the halvings of bisection, which may leave up to twice the steps needed.
  std::vector<double> times{t0_};
  reached = 0;
  for (double a = t0_; a < t1_;) {
    double bound = displacement_(a, t1_);
    double b = t1_;
    if (bound > tolerance) {
      double fits = 0, fails = t1_ - a;  // step lengths
      for (int halving = 0; halving < 20; ++halving) {
        const double length = 0.5 * (fits + fails);
        const double at = displacement_(a, a + length);
        if (at <= tolerance) fits = length, bound = at;
        else fails = length;
      }
      if (fits < min_step) {
        fits = std::min(min_step, t1_ - a);
        bound = displacement_(a, a + fits);
      }
      b = fits >= t1_ - a ? t1_ : a + fits;
    }
    reached = std::max(reached, bound);
    times.push_back(b);
    a = b;
  }
  return times;
}

RelativeMotion relative_motion(const scene::Reconfigurable& scene, int transition, int part, int relative_to,
                               double t0, double t1) {
  PartMotion b = part_motion(scene, transition, part);
  const double r_b = part_radius(scene.parts[part]);
  const Eigen::Vector3d c_b = scene.parts[part].center;
  if (relative_to < 0)
    return RelativeMotion(b.map, [displacement = b.displacement, r_b](double s, double e) { return displacement(r_b, s, e); },
                          t0, t1);
  PartMotion a = part_motion(scene, transition, relative_to);
  const Eigen::Vector3d c_a = scene.parts[relative_to].center;
  auto pose = [map_a = a.map, map_b = b.map](double t) { return Eigen::Isometry3d(map_a(t).inverse() * map_b(t)); };
  auto bound = [a, b, r_b, c_a, c_b](double s, double e) {
    const double rho = (b.map(s) * c_b - a.map(s) * c_a).norm() + r_b;
    return b.displacement(r_b, s, e) + a.displacement(rho, s, e);
  };
  return RelativeMotion(pose, bound, t0, t1);
}

}  // namespace reconfig::sweep
