#pragma once
/// @file
/// A planar linkage driving a transition: parts attached to its links move with them as the
/// motor turns from one angle to another, the linkage plane placed in 3D by a pose
/// (docs/file-formats.md, "Linkage-driven transitions").
///
/// The drive is compiled into ordinary `ScrewPosesTrack`s of the transition (one per attached
/// part, keys chosen adaptively so every point of the part stays within `tolerance` of where
/// the linkage puts it), so everything that reads tracks — `Reconfigurable::pose_at`, the
/// collision engine, the views — handles a driven transition unchanged. The description is
/// kept on the transition so saving writes the drive, not the compiled keys.

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "reconfig/linkage/linkage.h"
#include "reconfig/motion/pose.h"
#include "reconfig/scene/track.h"

namespace reconfig::scene {

struct Reconfigurable;
struct Transition;

/// A part carried by a link of the driving linkage.
struct LinkageAttachment {
  std::string part;
  /// The link frame: origin at joint `origin`, x axis toward joint `toward` (two joints of one
  /// link), z along the linkage plane's normal.
  std::string origin, toward;
  /// Places the part's rest geometry in the link frame as the plain rigid map
  /// `q = R p + x` (about the origin, not the part's center), in scene units.
  motion::Pose offset;
};

/// The drive of one transition.
struct LinkageDrive {
  /// The linkage file (absolute; the scene file stores it relative to itself), or empty when
  /// the linkage is written inline in the scene.
  std::optional<std::filesystem::path> file;
  linkage::Linkage linkage;
  /// The plane placement: the linkage point (x, y) is at `plane` applied (as a plain rigid
  /// map, about the origin) to (scale·x, scale·y, 0).
  motion::Pose plane;
  double scale = 1.0;  ///< scene units per linkage unit
  /// Motor angles in degrees, unwrapped (0 → 360 is one counterclockwise turn); over the
  /// transition's time [0, 1] the angle runs linearly from `from` to `to`.
  double from = 0.0, to = 0.0;
  std::vector<LinkageAttachment> attach;
  /// Largest distance (scene units) any point of a driven part may be from where the linkage
  /// puts it, in the compiled tracks.
  double tolerance = 1e-4;

  /// The tracks `compile_linkage_drive` produced (by part name); validate_scene checks that
  /// the transition's tracks of the driven parts still equal them (an edit of a driven
  /// part's keys is refused: edit the drive and recompile instead).
  std::map<std::string, ScrewPosesTrack> compiled;
  /// The largest deviation measured while compiling (≤ tolerance / 2 at the check times).
  double compiled_deviation = 0.0;

  /// Whether `part` is attached.
  bool drives(const std::string& part) const;
};

/// What compile_linkage_drive does with the driven parts' poses in the end states.
enum class DriveStatePoses {
  kFillMissing,  ///< a state that does not list the part gets the drive's pose; a listed pose must match
  kOverwrite,    ///< the end states always get the drive's poses (after editing a drive)
};

/// Compiles the drive of transition `transition` (which must have one) into tracks for the
/// attached parts and sets their poses in the `from` / `to` states (see DriveStatePoses).
///
/// Checks, each error naming the JSON path relative to the scene (file left empty):
/// attached parts exist, are attached once and have no other track in this transition
/// (`transitions[i].linkage.attach[k].part`); the link joints exist and share a link
/// (`….attach[k].link`); scale and tolerance are positive; the motor range holds the turn from
/// `from` to `to` (`transitions[i].linkage.motor`); a listed state pose matches the drive
/// (`states[s].poses.<part>`, with the expected pose in full precision).
/// @throws InputError
void compile_linkage_drive(Reconfigurable& scene, int transition,
                           DriveStatePoses state_poses = DriveStatePoses::kFillMissing);

/// Compiles every transition that has a drive, in transition order.
void compile_linkage_drives(Reconfigurable& scene, DriveStatePoses state_poses = DriveStatePoses::kFillMissing);

/// The exact poses (not the compiled track) the drive of `transition` gives part `part` at
/// times t ∈ [0, 1]: the oracle the compiled tracks are measured against.
/// @throws InputError if the part is not driven there or the linkage breaks at some t
std::vector<motion::Pose> linkage_drive_poses(const Reconfigurable& scene, int transition, int part,
                                              const std::vector<double>& times);

/// The first driven part of `transition` whose track no longer equals what its drive compiled
/// (or that has no track), or "" if all are intact (always "" without a drive).
std::string edited_driven_part(const Transition& transition);

}  // namespace reconfig::scene
