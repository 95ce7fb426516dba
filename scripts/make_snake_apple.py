#!/usr/bin/env python3
"""Writes examples/snake-apple.json: the dissertation's snake and the apple (Fig. 50, section 8.1).

A soft rubber tube (the snake) lies along +x on the ground plane z = -BELLY (z is up). Its head
face (the mouth, x = 0) is fixed. Its belly is a flat strip where the tube is cut by the ground
plane; those nodes are held by a planar constraint (normal z): they slide freely in the ground
plane but cannot leave it. The mouth is flared (a ball cut out of its end), so that a rigid
apple, a ball a little larger than the tube's bore, enters without touching the fixed ring.

The apple is a second body, a rigid region with prescribed keyframes (translations only): it
starts on the tube's axis just in front of the mouth, is pushed into it while rising to rest on
the floor of the bore, and then follows a zigzag parallel to the ground (sideways, y, by
+-ZIGZAG mm) toward the tail, where it stops. The tube bulges around it and slides sideways on
the ground with it; contact is material-depth contact between the apple and the snake (the
snake's self-contact too), in a static analysis. The apple, a solid ball, is deep everywhere, so
the snake's thin wall cannot slip through it; the penalty is 3 times the default automatic one
(penalty_scale 30), which keeps the penetration near 0.2 mm (0.3 mm on entering the mouth), well
below half the thinnest wall (3.5 mm, under the belly).

The keyframes are spaced along lambda in proportion to the path length, so that the apple moves
equally far in every load increment.

Usage: python3 scripts/make_snake_apple.py [OUTPUT]   (default examples/snake-apple.json)
"""

import json
import math
import pathlib
import sys

LENGTH = 140.0  # mm, mouth at x = 0, tail at x = LENGTH
OUTER = 12.0  # mm, outer radius of the tube
INNER = 7.5  # mm, radius of the bore (wall 4.5 mm)
BELLY = 11.0  # mm, the ground plane is z = -BELLY: the tube is cut flat there (bottom wall 3.5 mm)
FLARE = 10.4  # mm, radius of the ball cut out of the mouth (centre at x = 0): the mouth's opening
APPLE = 9.8  # mm, apple radius: 2.3 mm larger than the bore
RIDE = APPLE - INNER - 0.1  # mm, height (z) of the apple's centre in the tube: it rests on the bore's floor
START = -APPLE - 1.0  # mm, x of the apple's centre at lambda = 0 (on the axis): just in front of the mouth
ENTER = 18.0  # mm, x of the apple's centre once in the mouth, risen to RIDE; the zigzag begins here
END = LENGTH - 14.0  # mm, x of the apple's centre at the end: near the tail
ZIGZAG = 8.0  # mm, sideways (y) amplitude of the zigzag
HALF_WAVES = 4  # sideways swings between ENTER and END (back to y = 0 at the end)
ELEMENT_SIZE = 4.0  # mm, snake (the bore's curvature makes it finer there: 12 elements per turn)
APPLE_ELEMENT_SIZE = 3.5  # mm
PENALTY_SCALE = 30  # contact penalty = this * E / h; the default 10 lets the apple 0.46 mm in, 30 0.30 mm
INCREMENTS = 30


def path_points():
    """The apple's centre (x, y, z) at the keyframes: in front of the mouth, in it, then zigzag."""
    points = [(START, 0.0, 0.0), (ENTER, 0.0, RIDE)]
    stride = (END - ENTER) / HALF_WAVES
    for k in range(HALF_WAVES):
        # Each half wave goes out to +-ZIGZAG at its middle; the last one ends back on the axis.
        x_mid = ENTER + (k + 0.5) * stride
        points.append((x_mid, ZIGZAG if k % 2 == 0 else -ZIGZAG, RIDE))
    points.append((END, 0.0, RIDE))
    return points


def keyframes():
    points = path_points()
    lengths = [0.0]
    for p, q in zip(points, points[1:]):
        lengths.append(lengths[-1] + math.dist(p, q))
    keys = []
    for (x, y, z), s in zip(points, lengths):
        keys.append({"lambda": round(s / lengths[-1], 9),
                     "translation": [round(x - START, 9), round(y, 9), round(z, 9)]})
    return keys


def scene():
    snake_shape = {"difference": [
        {"intersection": [
            {"cylinder": {"base": [0, 0, 0], "axis": [LENGTH, 0, 0], "radius": OUTER}},
            {"box": {"min": [-1, -OUTER - 1, -BELLY], "max": [LENGTH + 1, OUTER + 1, OUTER + 1]}}]},
        {"cylinder": {"base": [-1, 0, 0], "axis": [LENGTH + 2, 0, 0], "radius": INNER}},
        {"sphere": {"center": [0, 0, 0], "radius": FLARE}}]}
    return {
        "name": "snake-apple",
        "description": (f"The dissertation's snake and the apple (Fig. 50): a soft rubber tube {LENGTH:g} mm long "
                        f"(outer radius {OUTER:g} mm, bore {INNER:g} mm, a flat belly on the ground plane z = "
                        f"{-BELLY:g}, z up) with its head (the mouth, x = 0) fixed and its belly held in the ground "
                        f"plane by a planar constraint; a rigid apple (radius {APPLE:g} mm) is moved by keyframes "
                        f"into the flared mouth and along a zigzag ({ZIGZAG:g} mm to either side) toward the tail, "
                        "in a static analysis. The tube bulges around the apple and slides on the ground. Written "
                        "by scripts/make_snake_apple.py."),
        "units": "mm, N, MPa",
        "materials": {"rubber": {"law": "mooney-rivlin", "C1": 0.05, "C2": 0.01, "a": 1.0}},
        "bodies": [
            {"name": "snake",
             "mesh": {"generate": {"element_size": ELEMENT_SIZE,
                                   "parts": [{"region": "rubber", "shape": snake_shape}]}},
             "regions": {"rubber": {"material": "rubber"}}},
            {"name": "apple",
             "mesh": {"generate": {"element_size": APPLE_ELEMENT_SIZE, "parts": [
                 {"region": "apple", "shape": {"sphere": {"center": [START, 0, 0], "radius": APPLE}}}]}},
             "regions": {"apple": {"rigid": {"prescribed": {"pivot": [START, 0, 0], "keyframes": keyframes()}}}}},
        ],
        "boundary_conditions": [
            {"name": "head", "type": "fixed",
             "nodes": {"body": "snake", "plane": {"point": [0, 0, 0], "normal": [1, 0, 0], "tolerance": 1e-6}}},
            # The flat strip on the ground, head nodes left out (they are fixed already).
            {"name": "belly", "type": "planar", "normal": [0, 0, 1],
             "nodes": {"body": "snake", "box": {"min": [1e-3, -OUTER, -BELLY], "max": [LENGTH, OUTER, -BELLY],
                                                "padding": 1e-6}}},
        ],
        "contact": {"penalty_scale": PENALTY_SCALE},
        "solver": {"increments": INCREMENTS},
        "output": {"vtu": True, "every": 1},
    }


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent / "examples" /
                       "snake-apple.json")
    out.write_text(json.dumps(scene(), indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
