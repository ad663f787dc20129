#pragma once
/// @file
/// Labels that fit their place: a text cut to a width of the current ImGui font, with "..." to
/// show it was cut, instead of a fixed number of characters or a cut mid-glyph by clipping.

#include <string>

namespace reconfig::studio {

/// `text` whole if it is at most `width` pixels wide in the current font, else its longest
/// beginning that fits followed by "..." (just "..." if nothing fits with it).
/// Needs a current ImGui context (the frame's font).
std::string fit_text(const std::string& text, float width);

}  // namespace reconfig::studio
