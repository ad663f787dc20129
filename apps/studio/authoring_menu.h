#pragma once
/// @file
/// The authoring menus: File > New / Import mesh, the Design menu (parts, states, transitions)
/// and the dialog they open (authoring_dialog.h). Each item ends in one of the studio's
/// authoring actions (authoring.cpp) or a scene command; bad input is a message in the status
/// bar, never a crash, and the design stays as it was. Its own state (the open dialog), drawn
/// by `draw_dialog` (like pip_panel.h).

#include <optional>

#include "authoring_dialog.h"

namespace reconfig::studio {

class Studio;

class AuthoringMenus {
 public:
  /// File menu items: New..., Import mesh...
  void draw_file_items(Studio& studio);
  /// The Design menu (with a design open).
  void draw_design_menu(Studio& studio);
  /// The open dialog, as a modal popup.
  void draw_dialog(Studio& studio);

  void open(AuthoringDialog dialog) { dialog_ = std::move(dialog); }
  const std::optional<AuthoringDialog>& dialog() const { return dialog_; }
  /// Performs what `dialog` asks for (its OK button). @return success; a refusal is in the
  /// status line
  bool accept(Studio& studio, const AuthoringDialog& dialog);

 private:
  void draw_part_menu(Studio& studio);
  void draw_state_menu(Studio& studio);
  void draw_transition_menu(Studio& studio);
  /// The dialog's fields. @return whether Enter was pressed in a text field
  bool draw_fields(const Studio& studio, AuthoringDialog& dialog);
  bool accept_edit(Studio& studio, const AuthoringDialog& dialog);

  std::optional<AuthoringDialog> dialog_;  ///< the open dialog
};

}  // namespace reconfig::studio
