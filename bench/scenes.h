#pragma once
/// @file
/// Benchmark scenes built from real meshes (the CGAL demo data of the libcgal-demo package).

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::bench {

/// `data/meshes/<name>` of the CGAL demo data, extracted once to the temporary folder, scaled
/// so that its bounding box is `size` wide at most, centered at the origin.
geometry::Mesh cgal_mesh(const std::string& name, double size = 1.0);

/// A part with edited (in-memory) geometry and its center of mass as pivot.
scene::Part make_part(const std::string& name, geometry::Mesh mesh);

/// Straight-line Bézier handles at the thirds of the chords (constant speed along each chord).
std::vector<motion::TranslationKey> polyline_keys(const std::vector<std::pair<double, Eigen::Vector3d>>& points);

/// A transition "start" → "end" in which only `part` moves.
scene::Transition one_track_transition(const std::string& name, const std::string& part, scene::KeyframedTrack track);

/// `still` rests at the origin; `moving` sweeps from x = −1.3 to x = 1.3 over a hump, turning 90°.
scene::Reconfigurable sweep_scene(const std::string& still, const std::string& moving);

/// 16 statues (1 m boxes, bunnies and armadillos in turn) in two rows of 8 along x, 1.2 m apart,
/// the rows 1.6 m apart (a 0.6 m corridor); a 0.45 m armadillo walks down the corridor turning
/// 90°, and swerves 0.2 m towards the fourth statue of the far row midway.
scene::Reconfigurable gallery_scene();

/// `parts` unit cubes on a square grid 3 m apart, of which the first `moving` rise 1 m: the
/// broad phase's case (issue 25: 10,000 parts took 4.7 GB and 46 s when every pair was kept).
scene::Reconfigurable crowd_scene(int parts = 10'000, int moving = 100);

}  // namespace reconfig::bench
