#pragma once
/// @file
/// The contact tolerance δ of a design: how deep parts may meet and still only touch.

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::collision {

/// The default δ as a fraction of the design's size.
inline constexpr double kDefaultContact = 1e-6;

/// The design's size: the largest absolute coordinate of any part's mesh (as in the scene
/// file's limits); 1 for a design without vertices.
double design_size(const scene::Reconfigurable& scene);

/// `contact` if positive, else `kDefaultContact` times the design's size.
double contact_tolerance(const scene::Reconfigurable& scene, double contact);

}  // namespace reconfig::collision
