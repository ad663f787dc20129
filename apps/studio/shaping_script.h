#pragma once
/// @file
/// The script actions of carving and the swept envelope (shaping_panel.h), for script.cpp:
///   carve PART by B[,C…] [offset E] [grid H] [timeout S]   carve and wait for the edit
///   envelope on|off                                         the View menu's toggle
///   expect-envelope [none]                                  the envelope is drawn (or not)

#include <string>
#include <vector>

#include "frontend.h"

namespace reconfig::studio {

/// Performs `action` if it is one of the above. @return false when it is not one of them;
/// else true, with `problem` empty on success or saying why the line failed
bool perform_shaping_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args,
                            std::string& problem);

}  // namespace reconfig::studio
