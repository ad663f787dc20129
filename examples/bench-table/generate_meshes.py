#!/usr/bin/env python3
"""Builds the bench-table example's meshes (run from this folder; writes meshes/*.obj).

A park bench that converts into a picnic table (reconfigurables paper, Figure 3): two side
frames with armrest posts, a slatted seat, armrests, and a three-board backrest that swings
forward and up to become the table top. All dimensions in metres.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from mesh_building import box as box_between, ear_clip, merge, write_obj  # noqa: E402


def box(center, size):
    """Axis-aligned box of the given size around center."""
    half = [x / 2 for x in size]
    return box_between([c - h for c, h in zip(center, half)], [c + h for c, h in zip(center, half)])


def extrude_x(profile, x0, x1):
    """Prism over a counter-clockwise (y, z) profile between x0 < x1; outward faces."""
    n = len(profile)
    v = [(x0, y, z) for y, z in profile] + [(x1, y, z) for y, z in profile]
    f = []
    for a, b, c in ear_clip(profile):
        f.append((n + a, n + b, n + c))  # +x cap: profile CCW seen from +x
        f.append((a, c, b))              # -x cap
    for i in range(n):
        j = (i + 1) % n
        f.append((i, j, n + j))
        f.append((i, n + j, n + i))
    return v, f


# Side frame seen from the side (y forward, z up): splayed legs joined under the seat, and a
# front post that carries the armrest.
FRAME = [(-0.30, 0.00), (-0.22, 0.00), (-0.10, 0.30), (0.10, 0.30), (0.18, 0.00), (0.26, 0.00),
         (0.20, 0.40), (0.20, 0.63), (0.14, 0.63), (0.14, 0.43), (-0.22, 0.43)]

os.makedirs("meshes", exist_ok=True)
write_obj("frame_left.obj", extrude_x(FRAME, -0.64, -0.60), "left side frame")
write_obj("frame_right.obj", extrude_x(FRAME, 0.60, 0.64), "right side frame")
write_obj("seat.obj", merge(*(box((0, y, 0.4495), (1.18, 0.12, 0.035)) for y in (-0.14, 0.0, 0.14))),
          "seat: three slats")
write_obj("backrest.obj", merge(*(box((0, -0.2, z), (1.30, 0.03, 0.13)) for z in (0.565, 0.72, 0.875))),
          "backrest: three boards, the table top once swung over")
