#pragma once
/// @file
/// Undoable edits of a transition's linkage drive (linkage_drive.h).

#include <memory>
#include <optional>
#include <string>

#include "reconfig/scene/command.h"
#include "reconfig/scene/linkage_drive.h"

namespace reconfig::scene {

/// Gives `transition` the drive `drive` (new or edited: linkage, plane, motor angles,
/// attachments, tolerance) and compiles it (compile_linkage_drive with
/// DriveStatePoses::kOverwrite): the driven parts get their compiled tracks and their poses in
/// the transition's end states follow the drive. Parts the old drive carried and the new one
/// does not lose their compiled tracks; a track a newly attached part had is replaced.
/// `std::nullopt` removes the drive but keeps the motion:
/// the compiled tracks stay as ordinary screw tracks.
///
/// `apply` validates the whole scene and throws InputError (leaving it untouched) if the drive
/// is broken or the new end-state poses disagree with another transition. Dirty: every part
/// the old or new drive carries, over [0, 1] of every transition that touches the end states.
std::unique_ptr<Command> set_linkage_drive(std::string transition, std::optional<LinkageDrive> drive);

}  // namespace reconfig::scene
