#include "reconfig/resolve/key_dofs.h"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <array>
#include <optional>
#include <variant>

#include "reconfig/common/input_error.h"
#include "reconfig/motion/pose_derivatives.h"

namespace reconfig::resolve {
namespace {

using Twists = Eigen::Matrix<double, 6, Eigen::Dynamic>;

scene::KeyframedTrack& keyframed_track(scene::Reconfigurable& scene, int transition, int part) {
  auto& tracks = scene.transitions.at(transition).tracks;
  return std::get<scene::KeyframedTrack>(tracks.at(scene.parts.at(part).name));
}

/// The block of ∂x/∂(key j), or zero when key j does not influence x(t).
Eigen::Matrix<double, 3, 10> translation_block(const std::vector<motion::TranslationKeyJacobian>& blocks, int key) {
  for (const auto& block : blocks)
    if (static_cast<int>(block.key) == key) return block.jacobian;
  return Eigen::Matrix<double, 3, 10>::Zero();
}

/// ω of the rigid rotation whose effect on the points e_k (relative to the center, world axes)
/// is the columns of M = [ω]×.
Eigen::Vector3d axial(const Eigen::Matrix3d& M) {
  return 0.5 * Eigen::Vector3d(M(2, 1) - M(1, 2), M(0, 2) - M(2, 0), M(1, 0) - M(0, 1));
}

/// ∂ω/∂(rotation key j) at t: 3 × 4 (δ_j, σ_j), from the rotation Jacobian of three points.
Eigen::Matrix<double, 3, 4> angular_block(const motion::SlerpRotationTrack& track, const Eigen::Matrix3d& R, int key,
                                          double t) {
  std::array<Eigen::Matrix<double, 3, 4>, 3> at_axis;  // ∂v/∂(key) at the point R offset = e_k
  for (int k = 0; k < 3; ++k) {
    at_axis[k].setZero();
    for (const auto& block : motion::rotation_jacobian(track, R.transpose().col(k), t))
      if (static_cast<int>(block.key) == key) at_axis[k] = block.jacobian;
  }
  Eigen::Matrix<double, 3, 4> omega;
  for (int c = 0; c < 4; ++c) {
    Eigen::Matrix3d M;
    for (int k = 0; k < 3; ++k) M.col(k) = at_axis[k].col(c);
    omega.col(c) = axial(M);
  }
  return omega;
}

void add_translation_dofs(const std::vector<motion::TranslationKey>& keys, const DofSelection& selection,
                          std::vector<KeyDof>& dofs) {
  const int m = static_cast<int>(keys.size());
  for (int j = 0; j < m; ++j) {
    const bool inner = j > 0 && j + 1 < m;
    if (inner || (selection.end_keys && m > 1)) dofs.push_back({DofKind::kTranslation, scene::KeyKind::kTranslation, j});
    const bool handles = selection.handles && (inner || selection.end_handles);
    if (handles && m > 1 && j > 0) dofs.push_back({DofKind::kHandleIn, scene::KeyKind::kTranslation, j});
    if (handles && m > 1 && j + 1 < m) dofs.push_back({DofKind::kHandleOut, scene::KeyKind::kTranslation, j});
    if (inner && selection.times) dofs.push_back({DofKind::kTime, scene::KeyKind::kTranslation, j});
  }
}

void add_rotation_dofs(const std::vector<motion::RotationKey>& keys, const DofSelection& selection,
                       std::vector<KeyDof>& dofs) {
  const int m = static_cast<int>(keys.size());
  for (int j = 0; j < m && m > 1; ++j) {
    const bool inner = j > 0 && j + 1 < m;
    if (selection.rotations && (inner || selection.end_keys))
      dofs.push_back({DofKind::kRotation, scene::KeyKind::kRotation, j});
    if (selection.times && inner) dofs.push_back({DofKind::kTime, scene::KeyKind::kRotation, j});
  }
}

void move_time(std::vector<double>& times, int key, double step, const std::string& where) {
  const double moved = times[key] + step;
  const bool ordered = (key == 0 || times[key - 1] < moved) && (key + 1 == static_cast<int>(times.size()) || moved < times[key + 1]);
  if (!ordered) throw InputError("", where, fmt::format("moving the key's time to {} would put the keys out of order", moved));
  times[key] = moved;
}

}  // namespace

std::vector<KeyDof> key_dofs(const scene::Reconfigurable& scene, int transition, int part,
                             const DofSelection& selection) {
  std::vector<KeyDof> dofs;
  const scene::KeyframedTrack* track = scene.keyframed_track(transition, part);
  if (!track) return dofs;
  add_translation_dofs(track->translation, selection, dofs);
  add_rotation_dofs(track->rotation, selection, dofs);
  return dofs;
}

int dof_coordinates(const std::vector<KeyDof>& dofs) {
  int n = 0;
  for (const KeyDof& dof : dofs) n += dof.size();
  return n;
}

Twists twist_jacobian(const scene::Reconfigurable& scene, int transition, int part, const std::vector<KeyDof>& dofs,
                      double t) {
  Twists J = Twists::Zero(6, dof_coordinates(dofs));
  const scene::KeyframedTrack* track = scene.keyframed_track(transition, part);
  if (!track || dofs.empty()) return J;
  const scene::Part& p = scene.parts.at(part);
  const motion::Pose pose = scene.pose_at(transition, part, t);
  const Eigen::Vector3d center = pose.apply(p.center, p.center);  // the pivot in the world
  const Eigen::Matrix3d R = pose.rotation.toRotationMatrix();
  std::vector<motion::TranslationKeyJacobian> translation;
  if (!track->translation.empty())
    translation = motion::translation_jacobian(motion::BezierTranslationTrack(track->translation), t);
  std::optional<motion::SlerpRotationTrack> rotation;
  if (!track->rotation.empty()) rotation.emplace(track->rotation);
  int column = 0;
  for (const KeyDof& dof : dofs) {
    if (dof.track == scene::KeyKind::kTranslation) {
      const Eigen::Matrix<double, 3, 10> b = translation_block(translation, dof.key);
      switch (dof.kind) {
        case DofKind::kTranslation:
          J.block<3, 3>(0, column) = b.middleCols<3>(0) + b.middleCols<3>(3) + b.middleCols<3>(6);
          break;
        case DofKind::kHandleIn: J.block<3, 3>(0, column) = b.middleCols<3>(0); break;
        case DofKind::kHandleOut: J.block<3, 3>(0, column) = b.middleCols<3>(6); break;
        default: J.block<3, 1>(0, column) = b.col(9); break;
      }
    } else if (rotation) {
      const Eigen::Matrix<double, 3, 4> omega = angular_block(*rotation, R, dof.key, t);
      const int first = dof.kind == DofKind::kTime ? 3 : 0;
      for (int c = 0; c < dof.size(); ++c) {
        const Eigen::Vector3d w = omega.col(first + c);
        J.block<3, 1>(0, column + c) = center.cross(w);  // u(y) = ω × (y − center)
        J.block<3, 1>(3, column + c) = w;
      }
    }
    column += dof.size();
  }
  return J;
}

namespace {

/// How a step moves the part's pose in the transition's first (0) and last (1) state.
struct StateMoves {
  std::array<Eigen::Vector3d, 2> translation = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::array<Eigen::Quaterniond, 2> rotation = {Eigen::Quaterniond::Identity(), Eigen::Quaterniond::Identity()};
  std::array<bool, 2> moved = {false, false};
};

/// Moves the part in the states whose end keys the step moved; every transition through them
/// follows (this one's end keys too).
void move_states(scene::Reconfigurable& scene, int transition, int part, const StateMoves& moves) {
  const scene::Transition& t = scene.transitions[transition];
  const std::string& name = scene.parts[part].name;
  for (int end = 0; end < 2; ++end) {
    if (!moves.moved[end]) continue;
    const std::string state = end == 0 ? t.from : t.to;
    motion::Pose pose = scene.states[scene.find_state(state)].pose_of(name);
    pose.translation += moves.translation[end];
    pose.rotation = (moves.rotation[end] * pose.rotation).normalized();
    scene::set_state_pose(state, name, pose)->apply(scene);
  }
}

}  // namespace

void displace_keys(scene::Reconfigurable& scene, int transition, int part, const std::vector<KeyDof>& dofs,
                   const Eigen::VectorXd& step) {
  scene::KeyframedTrack& track = keyframed_track(scene, transition, part);
  StateMoves states;
  int column = 0;
  for (const KeyDof& dof : dofs) {
    const Eigen::Vector3d d = dof.size() == 3 ? Eigen::Vector3d(step.segment<3>(column)) : Eigen::Vector3d::Zero();
    const int keys = static_cast<int>(dof.track == scene::KeyKind::kTranslation ? track.translation.size()
                                                                                 : track.rotation.size());
    const int end = dof.key == 0 ? 0 : (dof.key + 1 == keys ? 1 : -1);
    if (end >= 0 && (dof.kind == DofKind::kTranslation || dof.kind == DofKind::kRotation)) {
      states.moved[end] = true;
      if (dof.kind == DofKind::kTranslation) states.translation[end] += d;
      else if (d.norm() > 0) states.rotation[end] = Eigen::Quaterniond(Eigen::AngleAxisd(d.norm(), d.normalized())) * states.rotation[end];
      column += dof.size();
      continue;
    }
    const std::string where =
        fmt::format("transitions[{}].tracks.{}.{}[{}]", transition, scene.parts[part].name,
                    dof.track == scene::KeyKind::kTranslation ? "translation" : "rotation", dof.key);
    if (dof.kind == DofKind::kTime) {
      std::vector<double> times;
      if (dof.track == scene::KeyKind::kTranslation)
        for (const auto& key : track.translation) times.push_back(key.time);
      else
        for (const auto& key : track.rotation) times.push_back(key.time);
      move_time(times, dof.key, step[column], where + ".time");
      if (dof.track == scene::KeyKind::kTranslation) track.translation[dof.key].time = times[dof.key];
      else track.rotation[dof.key].time = times[dof.key];
    } else if (dof.kind == DofKind::kRotation) {
      auto& q = track.rotation[dof.key].rotation;
      if (d.norm() > 0) q = (Eigen::Quaterniond(Eigen::AngleAxisd(d.norm(), d.normalized())) * q).normalized();
    } else {
      auto& key = track.translation[dof.key];
      if (dof.kind != DofKind::kHandleOut) key.in += d;
      if (dof.kind == DofKind::kTranslation) key.point += d;
      if (dof.kind != DofKind::kHandleIn) key.out += d;
    }
    column += dof.size();
  }
  move_states(scene, transition, part, states);
}

std::string dof_kind_name(DofKind kind) {
  switch (kind) {
    case DofKind::kTranslation: return "translation";
    case DofKind::kHandleIn: return "handle_in";
    case DofKind::kHandleOut: return "handle_out";
    case DofKind::kRotation: return "rotation";
    case DofKind::kTime: return "time";
  }
  return "time";
}

}  // namespace reconfig::resolve
