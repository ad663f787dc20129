#!/usr/bin/env python3
"""Writes meshes/armrest.obj: the bench-table's armrest (a 0.05 x 0.38 x 0.04 m box centered
at the origin) as a closed, outward-oriented triangle mesh with 5 mm squares, so that a tool
can bend it (the scene's `box` part has only 8 vertices)."""

import os

SIZE = (0.05, 0.38, 0.04)
CELLS = (10, 76, 8)  # 5 mm squares


def main():
    index = {}
    vertices = []
    faces = []

    def vertex(i, j, k):
        key = (i, j, k)
        if key not in index:
            index[key] = len(vertices) + 1
            vertices.append(tuple(SIZE[a] * (key[a] / CELLS[a] - 0.5) for a in range(3)))
        return index[key]

    # Each side of the box: the axis it faces, its sign, and the two axes spanning it
    # (ordered so that u x v points outward).
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for sign in (0, 1):
            for a in range(CELLS[u]):
                for b in range(CELLS[v]):
                    def at(da, db):
                        key = [0, 0, 0]
                        key[axis] = sign * CELLS[axis]
                        key[u], key[v] = a + da, b + db
                        return vertex(*key)
                    quad = [at(0, 0), at(1, 0), at(1, 1), at(0, 1)]
                    if sign == 0:
                        quad.reverse()
                    faces.append((quad[0], quad[1], quad[2]))
                    faces.append((quad[0], quad[2], quad[3]))

    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "meshes", "armrest.obj")
    with open(path, "w") as out:
        out.write("# the bench-table armrest, 5 mm squares (generate_armrest.py)\n")
        for x, y, z in vertices:
            out.write(f"v {x:.6f} {y:.6f} {z:.6f}\n")
        for a, b, c in faces:
            out.write(f"f {a} {b} {c}\n")


if __name__ == "__main__":
    main()
