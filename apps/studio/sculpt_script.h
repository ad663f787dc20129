#pragma once
/// @file
/// The script actions of the sculpt mode (sculpt_panel.h), for script.cpp; they drive the
/// mouse as a designer would:
///   sculpt-mode on|off                          the K toggle (for the selected part)
///   sculpt-tool SHAPE SX SY SZ COATING          sphere|box|capsule|ellipsoid and its sizes,
///                                               or `part NAME COATING`: a part baked as the tool
///   sculpt-center X Y Z                         the tool's center in the part's rest frame
///   sculpt-rotation AX AY AZ DEGREES            the tool's rotation in the part's rest frame
///   sculpt-view +x|-x|+y|-y|+z                  the camera on that side, level (or from above)
///   sculpt-place X Y Z                          right-drag from the tool to where world point
///                                               (X, Y, Z) is drawn: the tool lands on the part
///   sculpt-drag DX DY DZ [wheel W] [steps N]    left-drag from the tool to where its center
///                                               moved by (DX, DY, DZ) (world) is drawn, in N
///                                               frames (8), W wheel steps half-way
///   sculpt-turn DEGREES [steps N]               left-drag in turn mode, round the tool on screen
///   sculpt-ring x|y|z DEGREES [steps N]         left-drag on the tool's ring about its own x, y
///                                               or z axis, round the tool's center on screen,
///                                               turning it by DEGREES about that axis

#include <string>
#include <vector>

#include "frontend.h"

namespace reconfig::studio {

/// Performs `action` if it is one of the above. @return false when it is not one of them;
/// else true, with `problem` empty on success or saying why the line failed
bool perform_sculpt_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args,
                           std::string& problem);

}  // namespace reconfig::studio
