#pragma once
/// @file
/// The planar linkage model: revolute joints, rigid links carrying two or more joints,
/// fixed joints, one crank motor, and tracking points (FORMATS.md, "reconfig-linkage").

#include <Eigen/Core>
#include <string>
#include <vector>

namespace reconfig::linkage {

/// A revolute (pin) joint. Its position is the one in the initial configuration x̄.
struct Joint {
  std::string name;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  bool fixed = false;  ///< pinned to the ground at `position` for all motor values
};

/// The crank: `joint` turns about the fixed joint `center`. The motor value is the absolute
/// angle (radians in the library, degrees in files and on the command line),
/// counterclockwise from +x, of the vector joint − center.
struct Motor {
  int center = -1;  ///< index into Linkage::joints
  int joint = -1;   ///< index into Linkage::joints
};

/// A point whose trajectory the user watches or edits; it sits on a joint.
struct TrackingPoint {
  std::string name;
  int joint = -1;  ///< index into Linkage::joints
};

/// A planar linkage in its initial configuration.
///
/// Links are rigid components given by the indices of the joints they carry (two or more,
/// distinct). The constant distances between joints of one link come from the initial
/// positions. Two joints that share a link are "neighbours".
struct Linkage {
  std::vector<Joint> joints;
  std::vector<std::vector<int>> links;
  Motor motor;
  std::vector<TrackingPoint> tracking_points;

  /// Index of the joint called `name`, or -1.
  int find_joint(const std::string& name) const;

  /// The initial joint positions. @return 2×#J, column j is joints[j].position
  Eigen::Matrix2Xd initial_positions() const;

  /// Sets the initial joint positions. @param X 2×#J
  void set_initial_positions(const Eigen::Matrix2Xd& X);

  /// The motor value (radians, in (−π, π]) of the initial configuration.
  double initial_motor_angle() const;

  /// For every joint, the indices of the links that carry it. @return #J lists
  std::vector<std::vector<int>> links_of_joints() const;

  /// For every joint, its neighbours (joints sharing a link), sorted, without duplicates.
  std::vector<std::vector<int>> neighbours() const;
};

}  // namespace reconfig::linkage
