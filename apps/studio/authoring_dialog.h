#pragma once
/// @file
/// The dialog the authoring menus open (authoring_menu.cpp): which edit it asks for and the
/// values typed into it so far.

#include <array>
#include <string>

namespace reconfig::studio {

struct AuthoringDialog {
  enum class Kind {
    kNewDesign,         ///< path: where the new design will be saved
    kImportMeshes,      ///< path: one or more mesh files, separated by ';'
    kAddPrimitive,      ///< name, shape, sizes
    kRenamePart,        ///< name
    kRecolorPart,       ///< color
    kReplaceMesh,       ///< path
    kDeletePart,        ///< confirmation (its keys go too)
    kAddState,          ///< name
    kRenameState,       ///< name
    kDeleteState,       ///< confirmation (its transitions go too)
    kAddTransition,     ///< name, from, to, choreography
    kRenameTransition,  ///< name
    kDuplicate,         ///< name (of the copy of a part or transition)
  };
  Kind kind = Kind::kNewDesign;
  int target = -1;         ///< the part, state or transition edited (index)
  bool transition = false; ///< kDuplicate: of a transition (else of a part)
  std::string text = {};   ///< the name or path typed
  int shape = 0;           ///< kAddPrimitive: 0 box, 1 cylinder, 2 sphere
  std::array<double, 3> sizes{0.1, 0.1, 0.1};
  std::array<float, 3> color{0.7f, 0.7f, 0.72f};
  int from = 0, to = 0;    ///< kAddTransition: state indices
  int choreography = 0;    ///< kAddTransition: 0 straight, 1 screw
  std::string message = {};  ///< kDeletePart / kDeleteState: what will go
  bool opened = false;     ///< the popup was opened (ImGui needs one OpenPopup)
};

}  // namespace reconfig::studio
