#pragma once
/// @file
/// The edit commands a designer performs (each undoable, each reporting its dirty ranges).

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/motion/bezier_translation_track.h"
#include "reconfig/motion/pose.h"
#include "reconfig/motion/slerp_rotation_track.h"
#include "reconfig/scene/command.h"
#include "reconfig/scene/track.h"

namespace reconfig::scene {

/// Which key list of a keyframed track an edit addresses.
enum class KeyKind { kTranslation, kRotation };

/// Replaces translation key `key` of `part`'s track in `transition` (time, point, handles).
/// The first and last keys of a track follow the state poses: of those only the handles may
/// change (to move them, edit the state instead).
std::unique_ptr<Command> set_translation_key(std::string transition, std::string part, int key,
                                             motion::TranslationKey value);

/// Replaces rotation key `key` (time, quaternion); same rules.
std::unique_ptr<Command> set_rotation_key(std::string transition, std::string part, int key,
                                          motion::RotationKey value);

/// Inserts a key at time t whose value is the current motion at t, so the motion keeps its
/// shape as far as the key type allows (a Bézier key is inserted by de Casteljau subdivision,
/// leaving the curve unchanged; a rotation key on the slerp arc). Creates the track (with
/// keys at the state poses) if the part had none.
std::unique_ptr<Command> insert_key(std::string transition, std::string part, KeyKind kind, double t);

/// Removes an inner key (not the first or last).
std::unique_ptr<Command> remove_key(std::string transition, std::string part, KeyKind kind, int key);

/// Sets `part`'s pose in `state`, and moves the end keys of every transition touching that
/// state with it (translation handles shift by the same offset), so the design stays valid.
std::unique_ptr<Command> set_state_pose(std::string state, std::string part, motion::Pose pose);

/// Places `part` at `pose` at time t of `transition` — what dragging a part in the editor does.
/// At t = 0 or t = 1 this edits the pose of the transition's from / to state (as
/// `set_state_pose`). At an inner time it sets a keyframe: the translation and rotation keys at
/// t are moved (translation handles shift with the point), and any that are missing are first
/// inserted where the motion already passes (so only the keyed component changes). A screw
/// track gets a screw pose at t. A part without a track gets one.
/// @param scene the scene the command will be applied to (names the transition's end states)
std::unique_ptr<Command> set_pose_at(const Reconfigurable& scene, std::string transition, std::string part, double t,
                                     motion::Pose pose);

/// Replaces the tracks of the parts named in `tracks` in `transition` at once (what automatic
/// resolution gives): one undoable step, refused if the scene it makes is invalid.
/// @param label  what the step says in the history ("resolve unfold automatically")
std::unique_ptr<Command> set_transition_tracks(std::string transition, std::map<std::string, Track> tracks,
                                               std::string label);

/// `steps` applied in order as one undoable step labelled `label` (reverted in reverse order);
/// when a step is refused, the ones before it are reverted and the refusal is thrown.
std::unique_ptr<Command> command_sequence(std::string label, std::vector<std::unique_ptr<Command>> steps);

/// Replaces a part's rest geometry; its pivot `center` is kept so poses keep their meaning.
/// `source` says where the new geometry comes from: `EditedMesh` (carved, sculpted: saving
/// writes it beside the design) or the `MeshFile` it was read from.
std::unique_ptr<Command> replace_part_mesh(std::string part, geometry::Mesh mesh, PartSource source = EditedMesh{});

/// Replaces the design's collision settings (refused if `settings.problem()` names one).
/// Every transition must then be detected again: the dirty set says the structure changed.
std::unique_ptr<Command> set_collision_settings(CollisionSettings settings);

}  // namespace reconfig::scene
