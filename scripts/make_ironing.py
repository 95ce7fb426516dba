#!/usr/bin/env python3
"""Writes examples/ironing.json: the ironing problem of Puso and Laursen (2004), frictional sliding.

A neo-Hookean slab 9 x 4 x 3 (E = 1, nu = 0.3) on a fixed base; a half-cylinder die of radius 3
(E = 1000, nu = 0.3), its flat top held by three planar conditions with their own amplitudes, is
pressed 1.4 into the slab during the first quarter of the load and then slid 4.0 along x,
friction coefficient 0.3. In steady sliding the friction force over the normal contact force is mu;
scripts/plot_ironing.py plots the die's reactions against the slide (docs/contact.md, "Friction").

Usage: /usr/bin/python3 scripts/make_ironing.py [--element-size H] [--increments N] [--mu MU]
       [--out FILE]
"""
import argparse
import json
import pathlib

PRESS = 0.25             # share of the load parameter spent pressing
DIE_CENTER = (2.5, 6.0)  # x and z of the die's axis at rest: its lowest line touches the slab's top
RADIUS = 3.0


def neo_hookean(E, nu):
    return {"law": "neo-hookean", "mu": E / (2 * (1 + nu)), "lambda": E * nu / ((1 + nu) * (1 - 2 * nu))}


def nodes_on_plane(body, point, normal):
    return {"body": body, "plane": {"point": point, "normal": normal, "tolerance": 1e-6}}


def scene(h, increments, mu):
    xc, zc = DIE_CENTER
    top = nodes_on_plane("die", [0, 0, zc], [0, 0, 1])
    return {
        "name": "ironing",
        "description": "Puso and Laursen's ironing problem (scripts/make_ironing.py): a half-cylinder die (R = 3, "
                       "E = 1000) pressed 1.4 into a neo-Hookean slab 9 x 4 x 3 (E = 1, nu = 0.3) and slid 4.0 "
                       "along it with friction coefficient 0.3; in steady sliding the friction force is mu times "
                       "the normal contact force.",
        "units": "mm, N, MPa",
        "materials": {"slab": neo_hookean(1.0, 0.3), "die": neo_hookean(1000.0, 0.3)},
        "bodies": [
            {"name": "slab",
             "mesh": {"generate": {"element_size": h, "parts": [
                 {"region": "slab", "shape": {"box": {"min": [0, 0, 0], "max": [9, 4, 3]}}}]}},
             "regions": {"slab": {"material": "slab"}}},
            {"name": "die",
             "mesh": {"generate": {"element_size": h, "parts": [{"region": "die", "shape": {"intersection": [
                 {"cylinder": {"base": [xc, 0, zc], "axis": [0, 4, 0], "radius": RADIUS}},
                 {"box": {"min": [xc - RADIUS, 0, zc - RADIUS], "max": [xc + RADIUS, 4, zc]}}]}}]}},
             "regions": {"die": {"material": "die"}}},
        ],
        "boundary_conditions": [
            {"name": "base", "type": "fixed", "nodes": nodes_on_plane("slab", [0, 0, 0], [0, 0, 1])},
            {"name": "die_z", "type": "planar", "nodes": top, "normal": [0, 0, 1], "displacement": -1.4,
             "amplitude": [[0, 0], [PRESS, 1], [1, 1]]},
            {"name": "die_x", "type": "planar", "nodes": top, "normal": [1, 0, 0], "displacement": 4.0,
             "amplitude": [[0, 0], [PRESS, 0], [1, 1]]},
            {"name": "die_y", "type": "planar", "nodes": top, "normal": [0, 1, 0], "displacement": 0},
        ],
        "contact": {"self_contact": False, "friction": {"coefficient": mu}},
        "solver": {"increments": increments},
        "output": {"vtu": True},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--element-size", type=float, default=0.6)
    parser.add_argument("--increments", type=int, default=40)
    parser.add_argument("--mu", type=float, default=0.3)
    parser.add_argument("--out", default=str(pathlib.Path(__file__).resolve().parent.parent / "examples" / "ironing.json"))
    args = parser.parse_args()
    text = json.dumps(scene(args.element_size, args.increments, args.mu), indent=1)
    pathlib.Path(args.out).write_text(text + "\n")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
