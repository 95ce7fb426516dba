#!/usr/bin/env python3
"""Writes examples/coiling-snake.json: the dissertation's coiling snake (Fig. 49, section 8.1).

A soft rubber rod (the snake, 150 mm long, radius 4 mm) has its tail face fixed; its head face is
moved 90 mm toward the tail while it turns two full turns about the rod's axis, with a small
sideways bow on the way, in a static analysis. The rod buckles, twists into a loop and the loop
closes on itself: self-contact keeps the coil from passing through itself.

The head's motion is a list of keyframes (lambda, translation, rotation about the head's centre),
8 of them so that consecutive keyframes are 90 degrees apart (slerp takes the shorter arc).

Usage: python3 scripts/make_coiling_snake.py [OUTPUT]   (default examples/coiling-snake.json)
"""

import json
import math
import pathlib
import sys

LENGTH = 150.0  # mm
RADIUS = 4.0  # mm
PULL = 0.6  # the head ends this fraction of the length closer to the tail
TURNS_DEG = 720.0  # about the rod's axis
BOW = 3.0  # mm, sideways, largest at lambda = 0.5
KEYFRAMES = 8


def scene():
    keys = [{"lambda": 0}]
    for k in range(1, KEYFRAMES + 1):
        lam = k / KEYFRAMES
        keys.append({
            "lambda": lam,
            "translation": [round(-PULL * LENGTH * lam, 9), round(BOW * math.sin(math.pi * lam), 9), 0.0],
            "rotation": {"axis": [1, 0, 0], "angle_deg": TURNS_DEG * lam},
        })
    return {
        "name": "coiling-snake",
        "description": ("The dissertation's coiling snake (Fig. 49): a soft rod 150 mm long (radius 4 mm) with its "
                        "tail fixed; its head is moved 90 mm toward the tail while turning two full turns about the "
                        "rod's axis (keyframes), in a static analysis. The rod buckles into a loop that closes on "
                        "itself; self-contact keeps it from passing through. Written by "
                        "scripts/make_coiling_snake.py."),
        "units": "mm, N, MPa",
        "materials": {"rubber": {"law": "mooney-rivlin", "C1": 0.05, "C2": 0.01, "a": 1.0}},
        "bodies": [{
            "name": "snake",
            "mesh": {"generate": {"element_size": 3.0, "parts": [
                {"region": "rubber", "shape": {"cylinder": {"base": [0, 0, 0], "axis": [LENGTH, 0, 0],
                                                            "radius": RADIUS}}}]}},
            "regions": {"rubber": {"material": "rubber"}},
        }],
        "boundary_conditions": [
            {"name": "tail", "type": "fixed",
             "nodes": {"plane": {"point": [0, 0, 0], "normal": [1, 0, 0], "tolerance": 1e-6}}},
            {"name": "head", "type": "prescribed",
             "nodes": {"plane": {"point": [LENGTH, 0, 0], "normal": [1, 0, 0], "tolerance": 1e-6}},
             "motion": {"pivot": [LENGTH, 0, 0], "keyframes": keys}},
        ],
        "contact": {},
        "solver": {"increments": 48},
        "output": {"vtu": True, "every": 1},
    }


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent / "examples" /
                       "coiling-snake.json")
    out.write_text(json.dumps(scene(), indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
