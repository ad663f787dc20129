#!/usr/bin/env python3
"""Writes the example linkages of this folder (run from anywhere: python3 make_examples.py).

Every initial configuration is assembled by intersecting circles, so all link lengths are
exact; the orientation of each reconstruction triangle is chosen here once and kept by the
simulator."""
import json, math, os

HERE = os.path.dirname(os.path.abspath(__file__))


def circle_intersection(p, rp, q, rq, left):
    """The point at distance rp from p and rq from q, to the left of p->q if `left`."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d2 = dx * dx + dy * dy
    a = (d2 + rp * rp - rq * rq) / (2 * d2)
    h2 = rp * rp / d2 - a * a
    assert h2 > 0, "circles do not meet"
    h = math.sqrt(h2) * (1 if left else -1)
    return [p[0] + a * dx - h * dy, p[1] + a * dy + h * dx]


def write(name, joints, links, motor, tracking):
    doc = {"format": "reconfig-linkage", "version": 1,
           "joints": [{"name": n, "position": [x, y], **({"fixed": True} if f else {})}
                      for n, (x, y), f in joints],
           "links": links, "motor": {"center": motor[0], "joint": motor[1]},
           "tracking_points": [{"name": t, "joint": j} for t, j in tracking]}
    with open(os.path.join(HERE, name), "w") as out:
        json.dump(doc, out, indent=2)
        out.write("\n")


# Theo Jansen's "holy numbers".
J = dict(a=38.0, b=41.5, c=39.3, d=40.1, e=55.8, f=39.4, g=36.7, h=65.7, i=49.0, j=50.0, k=61.9, l=7.8, m=15.0)


def jansen_leg(theta, mirror=False):
    """Joint positions of one Jansen leg at crank angle theta (the right leg is the mirror
    image of a left leg at crank angle pi - theta)."""
    t = math.pi - theta if mirror else theta
    O = [0.0, 0.0]
    B = [-J["a"], -J["l"]]
    C = [J["m"] * math.cos(t), J["m"] * math.sin(t)]
    U = circle_intersection(B, J["b"], C, J["j"], left=True)   # upper joint
    L = circle_intersection(B, J["c"], C, J["k"], left=False)    # lower joint
    E = circle_intersection(B, J["d"], U, J["e"], left=True)   # b-d-e triangle: |BE| = d, |UE| = e
    F = circle_intersection(E, J["f"], L, J["g"], left=False)   # knee
    P = circle_intersection(F, J["h"], L, J["i"], left=False)   # foot
    pts = dict(O=O, B=B, C=C, U=U, L=L, E=E, F=F, P=P)
    if mirror:
        pts = {n: [-x, y] for n, (x, y) in pts.items()}
    return pts


def leg_entries(prefix, pts, crank_tip):
    joints = [(prefix + "B", pts["B"], True)] + [(prefix + n, pts[n], False) for n in "ULEFP"]
    links = [[crank_tip, prefix + "U"], [crank_tip, prefix + "L"], [prefix + "B", prefix + "U", prefix + "E"],
             [prefix + "B", prefix + "L"], [prefix + "E", prefix + "F"], [prefix + "F", prefix + "L", prefix + "P"]]
    return joints, links


def jansen():
    theta = math.radians(0.0)
    pts = jansen_leg(theta)
    joints = [("O", pts["O"], True), ("C", pts["C"], False)]
    leg_joints, leg_links = leg_entries("", pts, "C")
    joints += leg_joints
    write("jansen.json", joints, [["O", "C"]] + leg_links, ("O", "C"), [("foot", "P")])


def strandbeest(pairs, name):
    theta = math.radians(0.0)
    joints = [("O", [0.0, 0.0], True)]
    crank = ["O"]
    links, tracking = [], []
    for p in range(pairs):
        phase = theta + 2 * math.pi * p / pairs
        tip = "C%d" % p
        joints.append((tip, [J["m"] * math.cos(phase), J["m"] * math.sin(phase)], False))
        crank.append(tip)
        for side, mirror in (("L", False), ("R", True)):
            pts = jansen_leg(phase, mirror)
            prefix = "%s%d." % (side, p)
            leg_joints, leg_links = leg_entries(prefix, pts, tip)
            joints += leg_joints
            links += leg_links
            tracking.append((prefix + "foot", prefix + "P"))
    write(name, joints, [crank] + links, ("O", "C0"), tracking)


def chebyshev_lambda():
    # Crank 1, ground 2, coupler 2.5, rocker 2.5; the tracer M lies on the coupler line at 5
    # from the crank pin (a straight-line stretch of its path).
    A, D = [0.0, 0.0], [2.0, 0.0]
    t = math.radians(60)
    B = [math.cos(t), math.sin(t)]
    C = circle_intersection(B, 2.5, D, 2.5, left=False)
    M = [B[0] + 2 * (C[0] - B[0]), B[1] + 2 * (C[1] - B[1])]
    joints = [("A", A, True), ("D", D, True), ("B", B, False), ("C", C, False), ("M", M, False)]
    write("chebyshev_lambda.json", joints, [["A", "B"], ["B", "C", "M"], ["D", "C"]], ("A", "B"), [("tracer", "M")])


def peaucellier_lipkin():
    # Arm Q-A of length 1 about Q = (1, 0) passes A through O; long arms O-B, O-D of 2.5;
    # rhombus sides 1. The tracer P stays on the line x = (2.5^2 - 1^2) / 2 = 2.625.
    O, Q = [0.0, 0.0], [1.0, 0.0]
    t = math.radians(30)
    A = [1 + math.cos(t), math.sin(t)]
    B = circle_intersection(O, 2.5, A, 1.0, left=True)
    Dj = circle_intersection(O, 2.5, A, 1.0, left=False)
    P = circle_intersection(Dj, 1.0, B, 1.0, left=False)
    joints = [("O", O, True), ("Q", Q, True), ("A", A, False), ("B", B, False), ("D", Dj, False), ("P", P, False)]
    links = [["Q", "A"], ["O", "B"], ["O", "D"], ["A", "B"], ["A", "D"], ["B", "P"], ["D", "P"]]
    write("peaucellier_lipkin.json", joints, links, ("Q", "A"), [("tracer", "P")])


def four_bar():
    # Grashof crank-rocker: ground 4, crank 1, coupler 3.5, rocker 3 (1 + 4 <= 3.5 + 3);
    # the coupler carries a tracer E off its line.
    A, D = [0.0, 0.0], [4.0, 0.0]
    t = math.radians(45)
    B = [math.cos(t), math.sin(t)]
    C = circle_intersection(B, 3.5, D, 3.0, left=False)
    E = circle_intersection(B, 2.0, C, 2.5, left=True)
    joints = [("A", A, True), ("D", D, True), ("B", B, False), ("C", C, False), ("E", E, False)]
    write("four_bar_crank_rocker.json", joints, [["A", "B"], ["B", "C", "E"], ["D", "C"]], ("A", "B"),
          [("coupler", "E")])


def klann():
    # Klann's topology (a Stephenson six-bar): crank O-C; ternary coupler {C, E, G}; lower
    # rocker B1-E; upper rocker B2-D; ternary leg {G, D, foot}. The dimensions are ours
    # (found by a seeded random search for a full crank rotation, well-conditioned
    # triangles and a long flat stretch of the foot path), not Klann's patent drawing.
    O, B1, B2 = [0.0, 0.0], [-1.649, -0.071], [-1.69, 1.018]
    t = math.radians(0)
    C = [0.6 * math.cos(t), 0.6 * math.sin(t)]
    E = circle_intersection(B1, 1.291, C, 1.860, left=False)
    G = circle_intersection(C, 2.367, E, 0.955, left=True)
    D = circle_intersection(B2, 1.657, G, 1.982, left=True)
    foot = circle_intersection(G, 2.273, D, 3.803, left=True)
    joints = [("O", O, True), ("B1", B1, True), ("B2", B2, True), ("C", C, False), ("E", E, False),
              ("G", G, False), ("D", D, False), ("foot", foot, False)]
    links = [["O", "C"], ["C", "E", "G"], ["B1", "E"], ["B2", "D"], ["G", "D", "foot"]]
    write("klann.json", joints, links, ("O", "C"), [("foot", "foot")])


def triad():
    # A complex kinematic loop (LinkEdit §3.3, "Limitations"): the ternary link {P1, P2, P3}
    # hangs from the crank tip C and from the fixed joints G and H by one bar each. No joint
    # has two known neighbours, so the closed-form rules are stuck; `reconfig` solves the
    # three joints together by Newton's method.
    joints = [("O", [0.0, 0.0], True), ("C", [1.0, 0.0], False), ("G", [5.0, 0.0], True), ("H", [3.0, 5.0], True),
              ("P1", [3.0, 1.0], False), ("P2", [5.0, 2.5], False), ("P3", [3.5, 3.0], False)]
    links = [["O", "C"], ["C", "P1"], ["G", "P2"], ["H", "P3"], ["P1", "P2", "P3"]]
    write("triad_complex_loop.json", joints, links, ("O", "C"), [("tip", "P3")])


if __name__ == "__main__":
    jansen()
    strandbeest(3, "strandbeest_3.json")
    strandbeest(10, "strandbeest_10.json")
    chebyshev_lambda()
    peaucellier_lipkin()
    four_bar()
    klann()
    triad()
