#pragma once
/// @file
/// Simple closed solids: box, cylinder, sphere. Each is closed, manifold and outward-oriented.

#include <Eigen/Core>

#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry {

/// An axis-aligned box centered at the origin: 8 vertices, 12 triangles.
/// @param size  edge lengths along x, y, z (each > 0)
Mesh make_box(const Eigen::Vector3d& size);

/// A cylinder along z, centered at the origin (z from -height/2 to height/2), its round side a
/// prism over a regular polygon inscribed in the circle: 2·segments + 2 vertices (ring vertices
/// and the two cap centers), 4·segments triangles. Its volume is
/// height · segments/2 · radius² · sin(2π/segments).
/// @param radius    circle radius (> 0)
/// @param height    length along z (> 0)
/// @param segments  number of sides of the polygon (≥ 3)
Mesh make_cylinder(double radius, double height, int segments = 48);

/// An icosphere centered at the origin: an icosahedron whose triangles are split into four
/// `subdivisions` times, every vertex pushed onto the sphere. 10·4^s + 2 vertices,
/// 20·4^s triangles; all vertices lie on the sphere, so the mesh is inscribed in it.
/// @param radius        sphere radius (> 0)
/// @param subdivisions  number of 1-to-4 splits (0 gives the icosahedron; ≤ 8)
Mesh make_sphere(double radius, int subdivisions = 3);

}  // namespace reconfig::geometry
