#!/usr/bin/env python3
"""Writes examples/knee-flexion.json: the seed's knee flexion (dissertation section 7, paper
section 6) on a generated right leg, built from the product's own shape generators.

Usage: /usr/bin/python3 scripts/make_knee.py [--element-size H] [--increments N] [--out PATH]

Coordinates in mm, the knee joint's centre at the origin: z up the leg, x to the front
(anterior), y across (the flexion axis). Stresses in kPa (the seed's Table 2 constants read as
kPa), so forces come out in mN.

Parts (one deformable body "leg" holding everything bonded together, and the rigid femur):
  femur      rigid, fixed: shaft (radius 14) and a bicondylar roller (two spheres of radius 22
             joined by a cylinder along y) under a short neck; body "femur"
  tibia      rigid, prescribed: plateau (radius 30, 2 mm below the condyles), shaft, tibial
             tuberosity; rotated 150 degrees about the y axis through the condyles' centre
  patella    rigid, free (6 DOF): a lens in front of the condyles
  ligament   patellar ligament (tendon, Table 2 blue) from the patella to the tuberosity
  tendon     quadriceps tendon (blue) above the patella, then the graded intermediate tissues
  graded_2   (magenta) and graded_1 (green), then the quadriceps muscle (yellow), rounded, in
  muscle     front of the femur with a 4 mm gap
  skin       skin-fat layer (Mooney-Rivlin C1 = 5, C2 = 1, a = 50): a 10 mm tube around the
             thigh and knee that fills the lower leg solid and is bonded there to the tibia
The thigh's upper cross-section (muscle and skin at z = 250) moves only in its plane.
Contact: the femur against the leg, and the leg against itself (skin folds, skin on muscle
and patella, patella on ...); bonded parts share nodes and carry no contact between them.
"""
import argparse
import json
import pathlib

THIGH, SHANK = 250.0, 250.0


def cyl(base, axis, radius):
    return {"cylinder": {"base": base, "axis": axis, "radius": radius}}


def box(lo, hi):
    return {"box": {"min": lo, "max": hi}}


def sphere(center, radius):
    return {"sphere": {"center": center, "radius": radius}}


def femur():
    return {"union": [
        cyl([0, 0, 20], [0, 0, THIGH - 20], 14),      # shaft
        cyl([0, 0, 0], [0, 0, 40], 18),               # neck above the condyles
        cyl([0, -21, 0], [0, 42, 0], 19),             # the groove between the condyles
        sphere([0, -21, 0], 22), sphere([0, 21, 0], 22)]}  # the condyles


def tibia():
    return {"union": [
        cyl([0, 0, -40], [0, 0, 16], 30),             # plateau, top 2 mm below the condyles
        cyl([0, 0, -SHANK], [0, 0, SHANK - 36], 15),  # shaft
        box([12, -10, -75], [38, 10, -50])]}          # tibial tuberosity


def patella():
    return {"intersection": [box([30, -20, 5], [44, 20, 45]), sphere([34, 0, 25], 22)]}


def rounded(lo, hi, radius):
    """A box in front of the femur, cut by the cylinder of `radius` about the leg's axis."""
    return {"intersection": [box(lo, hi), cyl([0, 0, lo[2] - 1], [0, 0, hi[2] - lo[2] + 2], radius)]}


def scene(element_size, increments):
    flexion = 150.0
    leg_parts = [
        {"region": "tibia", "shape": tibia()},
        {"region": "patella", "shape": patella()},
        {"region": "ligament", "shape": box([33, -10, -62], [41, 10, 10])},
        {"region": "tendon", "shape": box([30, -16, 40], [42, 16, 80])},
        {"region": "graded_2", "shape": rounded([26, -22, 80], [47, 22, 100], 56)},
        {"region": "graded_1", "shape": rounded([22, -28, 100], [52, 28, 120], 56)},
        {"region": "muscle", "shape": rounded([18, -34, 120], [56, 34, THIGH], 56)},
        {"region": "skin", "shape": {"difference": [
            cyl([0, 0, -SHANK], [0, 0, THIGH + SHANK], 70),
            cyl([0, 0, -70], [0, 0, THIGH + 71], 60)]}},
    ]
    return {
        "name": "knee-flexion",
        "description": "The seed's knee flexion (dissertation section 7, paper section 6) on a generated right leg "
                       "(scripts/make_knee.py): rigid femur fixed, rigid tibia turned 150 degrees about the "
                       "transverse axis through the condyles in 3-degree increments, rigid patella free, pulled "
                       "over the condyles by the patellar ligament; quadriceps muscle, graded tissues and tendons of "
                       "Table 2; a skin-fat layer bonded to the lower leg that folds behind the knee. Frictionless "
                       "material-depth contact between every pair of parts and self-contact of the skin.",
        "units": "mm, mN, kPa",
        "materials": {
            "tendon": {"law": "veronda-westmann", "alpha": 1400.0, "beta": 8.0, "a": 1000.0},
            "graded_2": {"law": "veronda-westmann", "alpha": 350.0, "beta": 8.0, "a": 500.0},
            "graded_1": {"law": "veronda-westmann", "alpha": 14.0, "beta": 8.0, "a": 200.0},
            "muscle": {"law": "veronda-westmann", "alpha": 7.0, "beta": 8.0, "a": 100.0},
            "skin": {"law": "mooney-rivlin", "C1": 5.0, "C2": 1.0, "a": 50.0},
        },
        "bodies": [
            {"name": "femur",
             "mesh": {"generate": {"element_size": element_size, "parts": [{"region": "femur", "shape": femur()}]}},
             "regions": {"femur": {"rigid": "fixed"}}},
            {"name": "leg",
             "mesh": {"generate": {"element_size": element_size, "parts": leg_parts}},
             "regions": {
                 "tibia": {"rigid": {"prescribed": {"rotation": {"axis": [0, 1, 0], "point": [0, 0, 0],
                                                                 "angle_deg": flexion}}}},
                 "patella": {"rigid": "free"},
                 "ligament": {"material": "tendon"},
                 "tendon": {"material": "tendon"},
                 "graded_2": {"material": "graded_2"},
                 "graded_1": {"material": "graded_1"},
                 "muscle": {"material": "muscle"},
                 "skin": {"material": "skin"}}},
        ],
        "boundary_conditions": [
            {"name": "thigh_cut", "type": "planar", "normal": [0, 0, 1],
             "nodes": {"body": "leg", "plane": {"point": [0, 0, THIGH], "normal": [0, 0, 1], "tolerance": 1e-6}}},
        ],
        "contact": {"self_contact": True},
        "solver": {"increments": increments},
        "output": {"vtu": True},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--element-size", type=float, default=12.0, help="target tet edge length (mm)")
    parser.add_argument("--increments", type=int, default=50, help="load increments over the 150 degrees")
    parser.add_argument("--out", default=str(pathlib.Path(__file__).resolve().parent.parent / "examples" /
                                             "knee-flexion.json"))
    args = parser.parse_args()
    path = pathlib.Path(args.out)
    path.write_text(json.dumps(scene(args.element_size, args.increments), indent=1) + "\n")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
