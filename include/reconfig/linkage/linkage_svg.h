#pragma once
/// @file
/// The linkage and its motion curves as an SVG picture.

#include <string>

#include "reconfig/linkage/linkage.h"

namespace reconfig::linkage {

struct SvgOptions {
  int samples = 360;     ///< points per motion curve
  double width = 800;    ///< picture width in pixels (the height follows the aspect ratio)
  std::string title;     ///< drawn at the top; empty: none
};

/// An SVG document: the motion curve of every moving joint over the motion range (tracking
/// points in color, other joints in gray), the links in the initial configuration (bars,
/// and translucent polygons for links with three or more joints), fixed joints as squares,
/// the motor joint in red, and the motion range ("full rotation" / "rocks between …").
/// @throws reconfig::InputError if the linkage cannot be simulated
std::string linkage_svg(const Linkage& linkage, const SvgOptions& options = {});

}  // namespace reconfig::linkage
