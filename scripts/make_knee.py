#!/usr/bin/env python3
"""Writes examples/knee-flexion.json (the main job): the seed's knee flexion (dissertation section 7,
paper section 6) on a generated right leg with a thigh full of muscle, built from the product's own
shape generators; with --thigh hull, examples/knee-flexion-hull.json, the earlier main job's leg,
whose skin-fat wraps a hull round the quadriceps group and leaves voids in the thigh.

Usage: /usr/bin/python3 scripts/make_knee.py [--element-size H] [--increments N] [--thigh muscle|hull]
                                             [--out PATH]

Coordinates in mm, the flexion axis is the y axis (through the centres of the condyles): z up the
leg, x to the front (anterior), y across. Stresses in kPa (the seed's Table 2 constants read as
kPa), so forces come out in mN. Proportions of an adult leg: radius 60, thigh and shank modelled
200 mm above and below the joint.

Parts (one deformable body "leg" holding everything bonded together, and the rigid femur):
  femur      rigid, fixed (body "femur"): two spherical condyles (radius 22) about the flexion
             axis with the trochlear groove between them, and the shaft in front of the axis
             (the condyles bulge behind it, so the tibia can turn 150 degrees without the rigid
             bones meeting)
  tibia      rigid, prescribed: plateau (radius 24, 2 mm below the condyles), shaft, tibial
             tuberosity; turned 150 degrees about the flexion axis in 3-degree increments
  patella    rigid, free (6 DOF): a ball in front of the groove, held only by its tendons
  ligament   patellar ligament (tendon, Table 2 blue) from the patella to the tuberosity
  tendon     quadriceps tendon (blue) above the patella, then the graded intermediate tissues
  graded_2   (magenta) and graded_1 (green) in front of the femur, rounded to the leg's
  graded_1   cross-section
  muscle     from MUSCLE_BASE (the graded tissues' base) up, the muscle fills the thigh inside the
             skin-fat layer in front of, beside and behind the femur (the quadriceps group, the
             vasti, the hamstrings), sliding on the femur across GAP; the graded tissues, listed
             before it, take its front
  skin       skin-fat (Mooney-Rivlin C1 = 5, C2 = 1, a = 50): a 10 mm layer round the thigh's
             muscle, bonded to it; below MUSCLE_BASE it fills the leg round the knee's parts,
             sliding on the femur, the patella, the ligament and the tendon across GAP, bonded to
             the tibia. No voids but the sliding gaps and, behind the quadriceps tendon, the
             suprapatellar pouch (8 mm between the tendon and the femur's gap, where the tendon
             glides on the femur). A fat pad bonded to the tendon's back there instead is crushed
             between tendon and femur to J = 0.005 by 150 degrees and costs a third more time
             (16 mm mesh: 520 s, 22 step cuts, against 386 s, 12, on the program of 2026-11-30).
The thigh's upper cross-section (muscle and skin-fat at z = 200) moves only in its plane.

--thigh hull (knee-flexion-hull.json, the main job until 2026-12-03) is the leg the seed's
"shrink wrap" gives: the skin-fat is the leg's cylinder minus a hull 4 mm around the femur, the
quadriceps group, the patella and the ligament, 10 mm over the muscles and solid behind the femur
and around the tibia. The hull wraps the quadriceps group more widely than the muscle it holds,
leaving up to 20 mm of empty space between the femur, the tendon, the graded tissues and the
skin, and the thigh has no muscle behind or beside the femur; its muscle is a block in front of
the femur from 115 mm up. It is easier to solve (16 mm: 479 Newton iterations and 2 step cuts
against the full thigh's 926 and 13) and stays as the speed benchmark's reference.
Contact: the femur against the leg (patella on the trochlea and condyles, muscle and skin-fat on
the bone) and the leg against itself (skin-fat on the muscle, tendons and patella, and folding
onto itself behind the knee); bonded parts share nodes and carry no contact between them.
"""
import argparse
import json
import pathlib

THIGH, SHANK = 200.0, 200.0  # lengths of the modelled thigh and shank above and below the joint (mm)
LEG_RADIUS = 60.0            # the skin's outer radius (mm)
SKIN = 10.0                  # the skin-fat layer's thickness over the muscles (mm)
FEMUR_PENALTY = 2000.0       # contact penalty femur / leg (kPa per mm of depth)
LEG_PENALTY = 300.0          # contact penalty of the leg on itself (kPa per mm of depth)
STIFF_SCALE = 5.0            # penalty factor of the bones and tendons: where two of them meet
                             # (patella on femur, tendon on femur) the penalty is 5x the pair's
GAP = 4.0                    # sliding gap between the skin-fat and the parts it is not bonded to (mm)
E = 16.0                     # the tibia's and the leg's axis lie this far in front of the flexion axis
MUSCLE_BASE = 75.0           # the muscle fills the thigh from here up (mm; the graded tissues' base)


def cyl(base, axis, radius):
    return {"cylinder": {"base": base, "axis": axis, "radius": radius}}


def box(lo, hi):
    return {"box": {"min": lo, "max": hi}}


def sphere(center, radius):
    return {"sphere": {"center": center, "radius": radius}}


def femur(grow=0.0):
    """Two spherical condyles about the flexion axis with the trochlear groove between them (the
    patella's track, from the front round to the back), and the shaft: narrow and flush with the
    groove's floor where it meets the condyles, wider above them. `grow` thickens every piece (the
    hull the skin-fat keeps its distance from)."""
    return {"union": [
        sphere([0, -21, 0], 22 + grow), sphere([0, 21, 0], 22 + grow),   # condyles
        cyl([0, -21, 0], [0, 42, 0], 19 + grow),                          # trochlear groove's floor
        cyl([8.5, 0, 0], [0, 0, THIGH], 10 + grow),                       # shaft at the condyles
        cyl([4, 0, 50], [0, 0, THIGH - 50], 13 + grow)]}                  # shaft above them


def tibia():
    return {"union": [
        cyl([E, 0, -40], [0, 0, 16], 24),                # plateau, 2 mm below the condyles
        cyl([E, 0, -SHANK], [0, 0, SHANK - 36], 14),     # shaft
        box([26, -10, -70], [46, 10, -48])]}             # tibial tuberosity


def patella():
    """A ball in front of the groove: no sharp rim to dig into the femur."""
    return sphere([37, 0, 18], 14)


def rounded(lo, hi, radius):
    """A box cut by the cylinder of `radius` about the leg's axis."""
    return {"intersection": [box(lo, hi), cyl([E, 0, lo[2] - 1], [0, 0, hi[2] - lo[2] + 2], radius)]}


def skin_fat():
    """--thigh hull: the leg's cylinder minus a hull around the femur, the quadriceps and its
    tendons, the patella and the patellar ligament, GAP away from them (the seed's "shrink wrap"
    hull): solid skin-fat behind the femur and around the tibia, to which it is bonded."""
    inner = LEG_RADIUS - SKIN
    hull = {"union": [
        femur(GAP),
        rounded([18, -36, 0], [E + inner + 1, 36, THIGH + 2], inner),   # quadriceps and tendons
        box([18, -22, -68], [54, 22, 0])]}                                # patella and ligament
    return {"difference": [cyl([E, 0, -SHANK], [0, 0, THIGH + SHANK], LEG_RADIUS), hull]}


def thigh_muscle():
    """The thigh inside the skin-fat layer from MUSCLE_BASE up, GAP away from the femur, in front
    of, beside and behind it."""
    return {"difference": [cyl([E, 0, MUSCLE_BASE], [0, 0, THIGH - MUSCLE_BASE], LEG_RADIUS - SKIN), femur(GAP)]}


def skin_fat_round_muscle():
    """The leg's cylinder minus a hull GAP round the femur, the patella, the ligament and the
    quadriceps tendon, reaching back to the femur's (the suprapatellar pouch).
    The thigh's muscle, listed before it, takes the thigh's inside above MUSCLE_BASE, so there the
    skin-fat is a layer bonded to it; below, it fills the knee round those parts, bonded to the tibia."""
    hull = {"union": [
        femur(GAP),
        box([19, -14 - GAP, -68], [50 + GAP, 14 + GAP, 32 + GAP]),       # patella and ligament
        box([19, -14 - GAP, 26], [44 + GAP, 14 + GAP, MUSCLE_BASE])]}   # the tendon and the pouch behind it
    return {"difference": [cyl([E, 0, -SHANK], [0, 0, THIGH + SHANK], LEG_RADIUS), hull]}


def scene(element_size, increments, thigh="muscle"):
    flexion = 150.0
    leg_parts = [
        {"region": "tibia", "shape": tibia()},
        {"region": "patella", "shape": patella()},
        {"region": "ligament", "shape": box([42, -9, -64], [50, 9, 14])},
        {"region": "tendon", "shape": box([30, -14, 26], [44, 14, 75])},
        {"region": "graded_2", "shape": rounded([35, -20, 75], [54, 20, 95], LEG_RADIUS - SKIN - GAP)},
        {"region": "graded_1", "shape": rounded([33, -26, 95], [58, 26, 115], LEG_RADIUS - SKIN - GAP)},
        {"region": "muscle", "shape": rounded([33, -32, 115], [E + 60, 32, THIGH], LEG_RADIUS - SKIN - GAP)},
        {"region": "skin", "shape": skin_fat()},
    ]
    name = "knee-flexion"
    description = ("The seed's knee flexion (dissertation section 7, paper section 6) on a generated right leg "
                   "(scripts/make_knee.py): rigid femur fixed, rigid tibia turned 150 degrees about the "
                   "transverse axis through the condyles in 3-degree increments, rigid patella free, pulled "
                   "over the condyles by the patellar ligament; quadriceps muscle, graded tissues and tendons of "
                   "Table 2; skin-fat filling the leg around them, bonded to the tibia, folding behind the knee. "
                   "Frictionless material-depth contact between every pair of parts and self-contact of the skin.")
    if thigh == "muscle":
        leg_parts[-2:] = [{"region": "muscle", "shape": thigh_muscle()},
                          {"region": "skin", "shape": skin_fat_round_muscle()}]
        description += (" The thigh has no voids: Table 2's muscle fills it in front of, beside and behind the "
                        "femur under a 10 mm skin-fat layer bonded to it.")
    else:
        name = "knee-flexion-hull"
        description += (" This variant (--thigh hull, the main job until 2026-12-03) is the seed's shrink wrap: "
                        "the skin-fat is the leg minus a hull round the femur and the quadriceps group, which "
                        "leaves voids in the thigh and no muscle behind or beside the femur.")
    return {
        "name": name,
        "description": description,
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
             "regions": {"femur": {"rigid": "fixed", "contact_penalty_scale": STIFF_SCALE}}},
            {"name": "leg",
             "mesh": {"generate": {"element_size": element_size, "parts": leg_parts}},
             "regions": {
                 "tibia": {"rigid": {"prescribed": {"rotation": {"axis": [0, 1, 0], "point": [0, 0, 0],
                                                                 "angle_deg": flexion}}}},
                 "patella": {"rigid": "free", "contact_penalty_scale": STIFF_SCALE},
                 "ligament": {"material": "tendon", "contact_penalty_scale": STIFF_SCALE},
                 "tendon": {"material": "tendon", "contact_penalty_scale": STIFF_SCALE},
                 "graded_2": {"material": "graded_2"},
                 "graded_1": {"material": "graded_1"},
                 "muscle": {"material": "muscle"},
                 "skin": {"material": "skin"}}},
        ],
        "boundary_conditions": [
            {"name": "thigh_cut", "type": "planar", "normal": [0, 0, 1],
             "nodes": {"body": "leg", "plane": {"point": [0, 0, THIGH], "normal": [0, 0, 1], "tolerance": 1e-6}}},
        ],
        # The patella is pressed onto the femur by the stretched extensor mechanism (Table 2's
        # Veronda-Westmann tissues stiffen exponentially; about 3 kN at 150 degrees), and at full
        # flexion the calf presses the thigh at a few hundred kPa: penalties well above the
        # automatic 10 E / h of the soft skin-fat, and five times more where bone or tendon meets
        # bone, keep the penetrations to a fraction of the skin's thickness.
        "contact": {"self_contact": True, "pairs": [{"bodies": ["femur", "leg"], "penalty": FEMUR_PENALTY},
                                                     {"bodies": ["leg", "leg"], "penalty": LEG_PENALTY}]},
        # 40 Newton iterations per step, not 25: in the knee's non-convex contact slides Newton often
        # converges only after 18-45 iterations; with 25 the 16 mm main job cut 13 steps and took 926
        # iterations, with 40 it cut 2 and took 640 (docs/solver.md, "Newton's iteration budget").
        "solver": {"increments": increments, "newton": {"max_iterations": 40}},
        "output": {"vtu": True},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--element-size", type=float, default=9.0,
                        help="target tet edge length (mm); 9 gives 8.9k nodes and 37k tets (the seed: 10k, 40k)")
    parser.add_argument("--increments", type=int, default=50, help="load increments over the 150 degrees")
    parser.add_argument("--thigh", choices=["muscle", "hull"], default="muscle",
                        help="muscle: the main job's thigh, full of muscle, no voids but the sliding gaps and the "
                             "suprapatellar pouch; hull: skin-fat over a hull round the quadriceps group, with voids "
                             "(knee-flexion-hull.json)")
    parser.add_argument("--out", help="default: examples/knee-flexion.json, with --thigh hull "
                                      "examples/knee-flexion-hull.json")
    args = parser.parse_args()
    written = scene(args.element_size, args.increments, args.thigh)
    path = pathlib.Path(args.out or pathlib.Path(__file__).resolve().parent.parent / "examples" /
                        (written["name"] + ".json"))
    path.write_text(json.dumps(written, indent=1) + "\n")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
