#!/usr/bin/env python3
"""Builds the kitchen example (run from this folder; writes meshes/*.obj and scene.json).

A space-saving kitchen along one wall, 22 rigid parts: a base cabinet run of three bays (three
drawers; a door with a pull-out shelf behind it; a door with a pull-out bin behind it), a
worktop with a hob and a slide-out worktop extension, a wall cabinet with three flap doors that
swing up and an extractor visor that slides out, and a dining corner: a fold-down table on a
wall rail with a swing-out bracket and two stools stored underneath.

States: "closed" (everything stowed), "open" (cooking: drawers, doors, flaps, shelf, bin,
visor and extension out) and "dining" (table down, bracket out, stools pulled out).
Transitions, each in a careless and a careful choreography:
  open_hasty    the shelf and the bin slide out while their doors are still opening: they go
                through the doors (collisions);
  open          the doors open first, then the shelf and the bin slide out (collision-free);
  dining_hasty  the bracket swings out while the stools are still stored under the table: it
                goes through both stools (collisions);
  dining        stools out first, then the bracket, then the table folds down (collision-free).

Every mesh is written in the closed state, so "closed" poses every part at the identity.
Hinged parts move by screw motions about their hinge (the pose keeps the hinge line fixed);
sliding parts by straight constant-speed Bézier keys. All dimensions in metres; x along the
wall, y out of the wall, z up.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from mesh_building import box, ear_clip, merge, write_obj  # noqa: E402


# A prism's profile coordinates (u, v) and its axis coordinate a, as (x, y, z): u × v = axis.
AXES = {"x": lambda a, u, v: (a, u, v), "y": lambda a, u, v: (v, a, u), "z": lambda a, u, v: (u, v, a)}


def extrude(profile, axis, a0, a1):
    """Prism over a counter-clockwise (u, v) profile between a0 < a1 along axis; outward faces.
    Profile coordinates: axis x → (y, z), axis y → (z, x), axis z → (x, y)."""
    n = len(profile)
    place = AXES[axis]
    v = [place(a0, p, q) for p, q in profile] + [place(a1, p, q) for p, q in profile]
    f = []
    for a, b, c in ear_clip(profile):
        f.append((n + a, n + b, n + c))  # + cap: profile counter-clockwise seen from +axis
        f.append((a, c, b))              # - cap
    for i in range(n):
        j = (i + 1) % n
        f.append((i, j, n + j))
        f.append((i, n + j, n + i))
    return v, f


def cylinder(cx, cy, r, z0, z1, segments=24):
    """Vertical cylinder (a regular prism) of radius r."""
    ring = [(cx + r * math.cos(2 * math.pi * k / segments), cy + r * math.sin(2 * math.pi * k / segments))
            for k in range(segments)]
    return extrude(ring, "z", z0, z1)


def u_profile(u0, u1, v0, v1, wall):
    """Counter-clockwise U (open towards +v): a bottom and two walls, `wall` thick."""
    return [(u0, v0), (u1, v0), (u1, v1), (u1 - wall, v1), (u1 - wall, v0 + wall), (u0 + wall, v0 + wall),
            (u0 + wall, v1), (u0, v1)]


def bar_handle(along, a0, a1, c, front, depth=0.034, bar=0.012, leg=0.012, thickness=0.016):
    """A bar handle standing `depth` proud of a front face at y = front (1 mm gap), running from
    a0 to a1 along x ("x", centred at height z = c) or along z ("z", centred at x = c)."""
    y0, y1 = front + 0.001, front + depth
    if along == "x":  # Π in the (x, y) plane, extruded along z
        pi = [(a0, y0), (a0 + leg, y0), (a0 + leg, y1 - bar), (a1 - leg, y1 - bar), (a1 - leg, y0), (a1, y0),
              (a1, y1), (a0, y1)]
        return extrude(pi, "z", c - thickness / 2, c + thickness / 2)
    # Π in the (y, z) plane, extruded along x: (u, v) = (y, z)
    pi = [(y0, a0), (y1, a0), (y1, a1), (y0, a1), (y0, a1 - leg), (y1 - bar, a1 - leg), (y1 - bar, a0 + leg),
          (y0, a0 + leg)]
    return extrude(pi, "x", c - thickness / 2, c + thickness / 2)


def center_of_mass(mesh):
    """Volume centroid of a closed, outward-oriented mesh (what the loader uses as the center)."""
    v, f = mesh
    volume, moment = 0.0, [0.0, 0.0, 0.0]
    for a, b, c in f:
        p, q, r = v[a], v[b], v[c]
        det = (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
               + p[2] * (q[0] * r[1] - q[1] * r[0]))
        volume += det / 6
        for k in range(3):
            moment[k] += det / 24 * (p[k] + q[k] + r[k])
    return [m / volume for m in moment]


# --- rigid motions -----------------------------------------------------------------------------

def quaternion(axis, degrees):
    half = math.radians(degrees) / 2
    return [math.cos(half)] + [a * math.sin(half) + 0.0 for a in axis]


def rotate(q, p):
    w, x, y, z = q
    # p' = p + 2w (u × p) + 2 u × (u × p), u = (x, y, z)
    t = [2 * (y * p[2] - z * p[1]), 2 * (z * p[0] - x * p[2]), 2 * (x * p[1] - y * p[0])]
    return [p[0] + w * t[0] + (y * t[2] - z * t[1]),
            p[1] + w * t[1] + (z * t[0] - x * t[2]),
            p[2] + w * t[2] + (x * t[1] - y * t[0])]


def hinge_pose(center, hinge, axis, degrees):
    """Pose (eq. 9: v = R (p − c) + c + x) turning a part about the line through `hinge` along
    `axis`: x = R (c − h) + h − c."""
    q = quaternion(axis, degrees)
    rc = rotate(q, [center[k] - hinge[k] for k in range(3)])
    return {"translation": [round(rc[k] + hinge[k] - center[k], 9) + 0.0 for k in range(3)],
            "rotation": [round(c, 9) + 0.0 for c in q]}


def slide_pose(offset):
    return {"translation": list(offset), "rotation": [1, 0, 0, 0]}


IDENTITY = slide_pose([0, 0, 0])


def screw_track(keys):
    """keys: [(time, pose)], joined by screw motions (a turn about the hinge stays one)."""
    return {"interpolation": "screw", "poses": [dict(time=t, **pose) for t, pose in keys]}


def slide_track(keys):
    """keys: [(time, offset)]; straight lines at constant speed between keys (thirds handles)."""
    out = []
    for k, (t, p) in enumerate(keys):
        prev = keys[k - 1][1] if k > 0 else p
        nxt = keys[k + 1][1] if k + 1 < len(keys) else p
        out.append({"time": t, "point": p,
                    "in": [round(p[i] + (prev[i] - p[i]) / 3, 9) for i in range(3)],
                    "out": [round(p[i] + (nxt[i] - p[i]) / 3, 9) for i in range(3)]})
    return {"translation": out}


# --- geometry (closed state) -------------------------------------------------------------------

PANEL = 0.018            # carcass panels
FRONT_Y = (0.602, 0.620)  # drawer and door fronts, 2 mm in front of the carcass (y = 0.6)
SIDES = [0.0, 0.591, 1.191, 1.782]  # carcass side panels (left edges): bays A, B, C between them
meshes = {}

carcass = [box((x, 0, 0.1), (x + PANEL, 0.6, 0.88)) for x in SIDES]
for left, right in zip(SIDES, SIDES[1:]):
    xa, xb = left + PANEL + 0.001, right - 0.001
    carcass += [box((xa, 0.019, 0.100), (xb, 0.6, 0.118)),    # bottom
                box((xa, 0.019, 0.862), (xb, 0.6, 0.880)),    # top
                box((xa, 0.000, 0.100), (xb, 0.018, 0.880))]  # back
meshes["carcass"] = (merge(*carcass), "base cabinet carcass: sides, bottoms, tops and backs of three bays")
meshes["plinth"] = (box((0, 0.50, 0), (1.8, 0.518, 0.098)), "plinth (kick board)")
meshes["worktop"] = (box((0, 0, 0.905), (1.8, 0.64, 0.945)), "worktop")
meshes["hob"] = (merge(box((0.65, 0.08, 0.947), (1.15, 0.52, 0.953)),
                       *(cylinder(x, y, r, 0.955, 0.975) for x, y, r in
                         ((0.78, 0.2, 0.07), (1.02, 0.2, 0.05), (0.78, 0.4, 0.05), (1.02, 0.4, 0.07)))),
                 "hob: glass plate and four burners")

# Bay A: three drawers (front, tray, handle).
DRAWERS = {"drawer_bottom": ((0.104, 0.344), (0.125, 0.31)),
           "drawer_middle": ((0.348, 0.588), (0.36, 0.55)),
           "drawer_top": ((0.592, 0.876), (0.60, 0.84))}
for name, ((f0, f1), (b0, b1)) in DRAWERS.items():
    meshes[name] = (merge(box((0.002, FRONT_Y[0], f0), (0.598, FRONT_Y[1], f1)),
                          extrude(u_profile(0.03, 0.598 - 0.002, b0, b1, 0.012), "x", 0.024, 0.585),
                          bar_handle("x", 0.2, 0.4, (f0 + f1) / 2, FRONT_Y[1])),
                    f"{name.replace('_', ' ')}: front, tray and handle")

# Bay B: a door hinged on its left edge, a pull-out shelf behind it.
meshes["cabinet_door_left"] = (merge(box((0.602, FRONT_Y[0], 0.104), (1.198, FRONT_Y[1], 0.876)),
                                     bar_handle("z", 0.6, 0.8, 1.15, FRONT_Y[1])),
                               "bay B door (hinged on the left) with handle")
meshes["pullout_shelf"] = (extrude(u_profile(0.03, 0.58, 0.40, 0.46, 0.012), "x", 0.625, 1.175),
                           "bay B pull-out shelf (a tray)")
# Bay C: a door hinged on its right edge, a pull-out bin behind it.
meshes["cabinet_door_right"] = (merge(box((1.202, FRONT_Y[0], 0.104), (1.798, FRONT_Y[1], 0.876)),
                                      bar_handle("z", 0.6, 0.8, 1.25, FRONT_Y[1])),
                                "bay C door (hinged on the right) with handle")
meshes["pullout_bin"] = (extrude(u_profile(0.03, 0.58, 0.13, 0.55, 0.012), "x", 1.225, 1.765),
                         "bay C pull-out bin")
# Worktop extension in the slot between the carcass top of bay C and the worktop.
meshes["sliding_worktop"] = (box((1.215, 0.02, 0.884), (1.775, 0.6, 0.900)), "slide-out worktop extension")

# Wall cabinet with three flap doors hinged along their top edge, and an extractor visor.
meshes["wall_cabinet"] = (merge(*(box((0.6 * k + 0.001, 0, 1.45), (0.6 * k + 0.599, 0.35, 2.15)) for k in range(3))),
                          "wall cabinet (three boxes)")
for k in range(3):
    meshes[f"wall_door_{k + 1}"] = (merge(box((0.6 * k + 0.002, 0.352, 1.45), (0.6 * k + 0.598, 0.370, 2.15)),
                                          bar_handle("x", 0.6 * k + 0.2, 0.6 * k + 0.4, 1.49, 0.370)),
                                    f"wall cabinet flap door {k + 1} (hinged along its top edge)")
meshes["extractor_visor"] = (box((0.65, 0.05, 1.40), (1.15, 0.33, 1.43)), "extractor hood visor")

# Dining corner: wall rail, fold-down table (stored folded up), swing-out bracket, two stools.
meshes["table_rail"] = (box((1.9, 0, 0.70), (2.7, 0.03, 0.77)), "wall rail carrying the table hinge")
meshes["table_top"] = (box((1.9, 0.04, 0.775), (2.7, 0.065, 1.475)), "table top, folded up against the wall")
meshes["table_bracket"] = (box((2.05, 0.035, 0.35), (2.545, 0.055, 0.74)), "table bracket, folded flat")
STOOL = [(0.08, 0.0), (0.11, 0.0), (0.11, 0.42), (0.35, 0.42), (0.35, 0.0), (0.38, 0.0), (0.38, 0.45), (0.08, 0.45)]
meshes["stool_left"] = (extrude(STOOL, "x", 1.97, 2.33), "folding stool, stored under the table")
meshes["stool_right"] = (extrude(STOOL, "x", 2.37, 2.68), "folding stool, stored under the table")

COLORS = {"carcass": [0.85, 0.84, 0.8], "plinth": [0.3, 0.3, 0.32], "worktop": [0.35, 0.33, 0.3],
          "hob": [0.1, 0.1, 0.12], "wall_cabinet": [0.85, 0.84, 0.8], "table_rail": [0.5, 0.5, 0.52],
          "table_top": [0.72, 0.52, 0.32], "table_bracket": [0.5, 0.5, 0.52], "stool_left": [0.6, 0.42, 0.26],
          "stool_right": [0.6, 0.42, 0.26], "extractor_visor": [0.7, 0.72, 0.75],
          "sliding_worktop": [0.45, 0.42, 0.38], "pullout_shelf": [0.7, 0.72, 0.75], "pullout_bin": [0.7, 0.72, 0.75]}
FRONT_COLOR = [0.42, 0.55, 0.5]

# --- states and transitions --------------------------------------------------------------------

centers = {name: center_of_mass(mesh) for name, (mesh, _) in meshes.items()}
Z, X = (0, 0, 1), (1, 0, 0)
HINGES = {  # part: (point on the hinge line, axis, opening angle in degrees)
    "cabinet_door_left": ((0.602, FRONT_Y[1], 0), Z, 90),
    "cabinet_door_right": ((1.798, FRONT_Y[1], 0), Z, -90),
    "wall_door_1": ((0, 0.370, 2.15), X, 90),
    "wall_door_2": ((0, 0.370, 2.15), X, 90),
    "wall_door_3": ((0, 0.370, 2.15), X, 90),
    "table_top": ((0, 0.04, 0.775), X, -90),
    "table_bracket": ((2.555, 0.045, 0), Z, -90),
}
SLIDES = {"drawer_bottom": [0, 0.4, 0], "drawer_middle": [0, 0.4, 0], "drawer_top": [0, 0.4, 0],
          "pullout_shelf": [0, 0.5, 0], "pullout_bin": [0, 0.42, 0], "sliding_worktop": [0, 0.45, 0],
          "extractor_visor": [0, 0.2, 0], "stool_left": [0, 0.75, 0], "stool_right": [0, 0.75, 0]}
OPEN = ["drawer_bottom", "drawer_middle", "drawer_top", "cabinet_door_left", "cabinet_door_right", "pullout_shelf",
        "pullout_bin", "sliding_worktop", "wall_door_1", "wall_door_2", "wall_door_3", "extractor_visor"]
DINING = ["table_top", "table_bracket", "stool_left", "stool_right"]


def moved(name):
    if name in HINGES:
        hinge, axis, degrees = HINGES[name]
        return hinge_pose(centers[name], hinge, axis, degrees)
    return slide_pose(SLIDES[name])


def track(name, t0, t1):
    """The part stays put until t0, moves to its moved pose over [t0, t1], then stays."""
    hinged = name in HINGES
    start, end = (IDENTITY, moved(name)) if hinged else ([0, 0, 0], SLIDES[name])
    keys = [(0.0, start)] + ([(t0, start)] if t0 > 0 else []) + ([(t1, end)] if t1 < 1 else []) + [(1.0, end)]
    return screw_track(keys) if hinged else slide_track(keys)


def transition(name, to, timing, note):
    return {"name": name, "from": "closed", "to": to, "_note": note,
            "tracks": {part: track(part, *timing[part]) for part in timing}}


def timing_of(parts, default, **special):
    return {part: special.get(part, default) for part in parts}


scene = {
    "format": "reconfig-scene", "version": 1, "units": "m",
    "parts": [{"name": name, "mesh": f"meshes/{name}.obj", "color": COLORS.get(name, FRONT_COLOR)} for name in meshes],
    "states": [
        {"name": "closed", "poses": {}},
        {"name": "open", "poses": {name: moved(name) for name in OPEN}},
        {"name": "dining", "poses": {name: moved(name) for name in DINING}},
    ],
    "transitions": [
        transition("open_hasty", "open", timing_of(OPEN, (0.0, 0.5), extractor_visor=(0.3, 0.8),
                                                   sliding_worktop=(0.2, 0.7)),
                   "shelf and bin slide out while their doors open: collisions"),
        transition("open", "open", timing_of(OPEN, (0.0, 0.5), extractor_visor=(0.3, 0.8), sliding_worktop=(0.2, 0.7),
                                             pullout_shelf=(0.5, 1.0), pullout_bin=(0.5, 1.0)),
                   "doors first, then shelf and bin: collision-free"),
        transition("dining_hasty", "dining", timing_of(DINING, (0.3, 0.7), table_bracket=(0.0, 0.4),
                                                       table_top=(0.6, 1.0)),
                   "bracket swings out before the stools are out: collisions"),
        transition("dining", "dining", timing_of(DINING, (0.0, 0.4), table_bracket=(0.4, 0.7), table_top=(0.6, 1.0)),
                   "stools, then bracket, then table: collision-free"),
    ],
}
# The scene format has no comments: the notes stay in this script and the README.
for t in scene["transitions"]:
    del t["_note"]

def to_json(value, indent=""):
    """JSON with one line per part, state pose and key (lists of numbers stay on one line)."""
    inner = indent + "  "
    if isinstance(value, dict) and not is_leaf(value):
        items = [f"{inner}{json.dumps(k)}: {to_json(v, inner)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + indent + "}"
    if isinstance(value, list) and value and not is_leaf(value):
        return "[\n" + ",\n".join(inner + to_json(v, inner) for v in value) + "\n" + indent + "]"
    return json.dumps(value)


def is_leaf(value):
    """Printed on one line: numbers, lists of numbers, dicts whose values are such."""
    if isinstance(value, dict):
        return all(not isinstance(v, dict) and is_leaf(v) for v in value.values())
    if isinstance(value, list):
        return all(isinstance(v, (int, float)) for v in value)
    return True


if __name__ == "__main__":
    os.makedirs("meshes", exist_ok=True)
    for name, (mesh, comment) in meshes.items():
        write_obj(name + ".obj", mesh, comment)
    with open("scene.json", "w") as out:
        out.write(to_json(scene) + "\n")
    print(f"{len(meshes)} parts, {sum(len(m[1]) for m, _ in meshes.values())} triangles")
