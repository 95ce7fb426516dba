#!/usr/bin/env python3
"""Writes examples/vh-knee-flexion.json: the seed's knee flexion (dissertation section 7, paper
section 6) on the Visible Human Male's right knee and skin (HRA 3D Reference Object Library v1.1,
docs/vh-knee.md), meshed by sinew from the surfaces.

Usage: /usr/bin/python3 scripts/make_vh_knee.py [--element-size H] [--increments N] [--angle DEG]
                                                [--muscle-law LAW] [--penetration-tolerance MM]
                                                [--tibiofemoral-space MM] [--tendon-gap-end round|flat] [--out PATH]

The scene works in the data's own frame, in mm (the files are in metres: unit_scale 1000): +y up,
+z anterior, +x to the subject's left (medial for this right leg). Stresses in kPa (Table 2 read
as kPa), forces in mN. The landmark coordinates below were measured on the HRA meshes (their
vertex extremes and the centroids of the enthesis patches); the construction is documented in
docs/vh-knee.md.

Bodies:
  femur   rigid, fixed: VH_M_femur_R (3 holes filled) below the thigh's cut
  leg     one body, its parts bonded (shared nodes), first listed wins where they overlap:
    tibia     rigid, prescribed: VH_M_tibia_R and VH_M_fibula_R above the shank's cut, turned 150
              degrees about the axis through the femoral epicondyles in 50 increments of 3
    patella   rigid, free: VH_M_patella_R
    ligament  patellar ligament (tendon): a rod from the patella's apex to the tibial tuberosity
    tendon    quadriceps tendon, then the graded tissues of Table 2 (graded_2, graded_1): rods
    graded_2  up the front of the femur from the patella's base
    graded_1
    muscle    the thigh inside the skin-fat layer from 75 mm above the joint line up, not taken
              above: the quadriceps, vasti and hamstrings (the data has none). Mooney-Rivlin by
              default, Table 2's Veronda-Westmann with --muscle-law veronda-westmann (MUSCLE_LAWS)
    skin      skin-fat: the skin cropped 200 mm above and below the joint line, a layer
              SKIN_FAT mm thick (Mooney-Rivlin 5 / 1 / 50 kPa); below the muscle it fills the
              leg's inside, the shank's muscles included
  Every soft part keeps GAP mm from the femur, which it slides on (contact); the soft tissue
  slides on the quadriceps tendon, the patella and the ligament across SLIDE mm. Elsewhere the
  bonded parts have no gaps, so the leg has no voids. The thigh's cut moves only in its plane.
Left out: the menisci and the articular cartilage (docs/vh-knee.md says why).
"""
import argparse
import json
import pathlib

JOINT_Y = -420.0          # the joint line (mm)
CROP = 200.0              # the leg is kept this far above and below it (mm)
SKIN_FAT = 8.0            # the skin-fat layer's thickness (mm)
GAP = 2.0                 # the soft tissue's distance from the femur (mm)
CARTILAGE = 3.0           # the patella's articular cartilage, rigid with it (mm)
MUSCLE_BASE_Y = JOINT_Y + 75.0  # below this the leg is skin-fat, not muscle (mm)
SLIDE = 3.0               # the gap across which the soft tissue slides on the tendons and the patella (mm)
PF_CAVITY = 14.0          # reach of the patellofemoral joint space (mm)
TF_CAVITY = 16.0          # reach of the tibiofemoral joint space (mm)
FEMUR_PENALTY = 8000.0    # contact penalty femur / leg (kPa per mm of depth)
LEG_PENALTY = 300.0       # contact penalty of the leg on itself
STIFF_SCALE = 5.0         # penalty factor of the bones and tendons
PENETRATION_TOLERANCE = 0.6  # adaptive penalty: a pair's penalty grows while it penetrates deeper (mm; 0.8 overshot 10 % of SKIN_FAT)
LATERAL_EPICONDYLE = [-172.85, -385.48, -25.22]  # centroid of VH_M_lateral_epicondylar_enthesis_R
MEDIAL_EPICONDYLE = [-87.83, -393.84, -26.16]    # centroid of VH_M_medial_epicondylar_enthesis_R
PATELLA_APEX = [-150.65, -406.23, 41.35]         # lowest vertex of VH_M_patella_R
PATELLA_BASE = [-148.07, -360.14, 39.62]         # highest vertex of VH_M_patella_R
TUBEROSITY = [-154.32, -460.66, 16.97]           # most anterior vertex of VH_M_tibia_R, 40-60 mm below the joint
KNEE_SOURCE = ("HRA 3D Reference Object Library v1.1, 'VH_M_Knee_R.glb' (3D Reference Organ for Knee, Male, "
               "Right; https://doi.org/10.48539/HBM546.WMLL.993, https://humanatlas.io/3d-reference-library)")
SKIN_SOURCE = ("HRA 3D Reference Object Library v1.1, 'VH_M_Skin.glb' (3D Reference Organ for Skin, Male; "
               "HuBMAP ID HBM592.CTHB.237, https://humanatlas.io/3d-reference-library)")


# The muscle's law. Table 2 gives Veronda-Westmann (alpha 7 kPa, beta 8) with the quadriceps' fibers;
# the paper's pictures were made with Mooney-Rivlin only (paper section 6), and the dissertation
# (section 9.2.1) says Veronda-Westmann with a large beta needs a full dynamic simulation. Run
# quasi-statically on this leg, Table 2's muscle stops the knee near 100 degrees and Mooney-Rivlin
# reaches 137 (both with plain penalties; docs/vh-knee.md), so Mooney-Rivlin is the default. The tendon and the graded tissues
# keep Table 2's laws either way.
MUSCLE_LAWS = {
    "mooney-rivlin": {"law": "mooney-rivlin", "C1": 5.0, "C2": 1.0, "a": 50.0},
    "veronda-westmann": {"law": "veronda-westmann", "alpha": 7.0, "beta": 8.0, "a": 100.0,
                         "fiber": {"alpha": 5.0, "beta": 2.0, "direction": [0.0, 1.0, 0.0]}},
}


def surface(name):
    return {"surface": name}


def capsule(a, b, radius):
    return {"capsule": {"a": a, "b": b, "radius": radius}}


def inside_leg(solid, tibiofemoral_space, pouch=False):
    """The solid, cropped to the leg between the cuts, kept GAP away from the femur and out of the
    joint spaces (and of the suprapatellar pouch, for the tissue around the quadriceps tendon)."""
    crop = [{"half_space": {"point": [0, JOINT_Y + CROP, 0], "normal": [0, 1, 0]}},
            {"half_space": {"point": [0, JOINT_Y - CROP, 0], "normal": [0, -1, 0]}},
            {"half_space": {"point": [0, 0, 0], "normal": [1, 0, 0]}},  # the right leg only (x < 0)
            surface("skin")]
    # Cheap tests first: a point fails the crop before the costly distance queries are made.
    return {"difference": [{"intersection": crop + [solid]}, {"offset": {"surfaces": ["femur"], "distance": GAP}},
                           joint_cavity("patella", PF_CAVITY), joint_cavity("tibia", tibiofemoral_space)]
            + ([SUPRAPATELLAR_POUCH] if pouch else [])}


# The suprapatellar pouch: the space between the quadriceps tendon and the femur, up to the graded
# tissues (points within PF_CAVITY of the femur and of the tendon's rod grown by PF_CAVITY). Without
# it the muscle under the tendon is crushed against the trochlea as the tendon wraps it (a full run
# stopped at 67 degrees with J = 0.007 there).
SUPRAPATELLAR_POUCH = {"intersection": [
    {"capsule": {"a": [-148.07, -364.14, 31.62], "b": [-131.0, -300.0, 28.0], "radius": 7.0 + PF_CAVITY}},
    {"offset": {"surfaces": ["femur"], "distance": PF_CAVITY}}]}


def joint_cavity(bone, reach):
    """The joint space between a bone and the femur (points within `reach` of both): no soft tissue
    there, so the bones meet each other (through the patella's cartilage) instead of crushing tissue
    bonded to them."""
    return {"intersection": [{"offset": {"surfaces": [bone], "distance": reach}},
                             {"offset": {"surfaces": ["femur"], "distance": reach}}]}


def cut_plane(y, h):
    """The nodes of a cut (within h / 10 of the plane: the mesher places the cap's nodes on it to
    round-off, its rim within the facet distance); faces there are the model's boundary, not a
    surface that touches anything, so they take no part in contact (docs/contact.md)."""
    return {"plane": {"point": [0, y, 0], "normal": [0, 1, 0], "tolerance": round(h / 10, 3)}}


def lerp(a, b, s):
    return [a[i] + s * (b[i] - a[i]) for i in range(3)]


def tendon_gap(base, t1, gap_end):
    """The quadriceps tendon's rod grown by SLIDE, across which the muscle and the skin-fat slide.
    gap_end "round" ends it at the tendon's top (t1) with the rod's hemisphere; "flat" with a plane
    normal to the tendon there, which leaves no thin wedge of muscle bonded to graded_2 inside the
    gap's mouth (docs/vh-knee.md compares the two)."""
    rod = capsule(base, t1, 7.0 + SLIDE)
    if gap_end == "round":
        return rod
    axis = [t1[i] - base[i] for i in range(3)]
    return {"intersection": [rod, {"half_space": {"point": t1, "normal": axis}}]}


def sliding_sleeve(base, t1, gap_end):
    """What the skin-fat slides on below MUSCLE_BASE_Y: the patella (with its cartilage), the
    patellar ligament and the quadriceps tendon, each grown by SLIDE. Cut out of the skin-fat, this
    leaves a SLIDE-wide gap, so the layer glides over them instead of being bonded (docs/vh-knee.md)."""
    ligament = capsule(lerp(PATELLA_APEX, PATELLA_BASE, 0.15), lerp(TUBEROSITY, PATELLA_APEX, 0.05), 5.0 + SLIDE)
    below_muscle = {"half_space": {"point": [0, MUSCLE_BASE_Y, 0], "normal": [0, 1, 0]}}
    return {"union": [{"intersection": [below_muscle, {"union": [
        {"offset": {"surfaces": ["patella"], "distance": CARTILAGE + SLIDE}}, ligament]}]},
        tendon_gap(base, t1, gap_end)]}


def scene(element_size, increments, angle_deg=150.0, muscle_law="mooney-rivlin", penetration_tolerance=PENETRATION_TOLERANCE,
          tibiofemoral_space=TF_CAVITY, gap_end="round"):
    h = element_size

    def inside(solid, pouch=False):
        return inside_leg(solid, tibiofemoral_space, pouch)

    knee = {"file": "VH_M_Knee_R.glb", "unit_scale": 1000.0, "source": KNEE_SOURCE}
    surfaces = {
        "femur": dict(knee, mesh="VH_M_femur_R", repair={"fill_holes": True}),
        "tibia": dict(knee, mesh="VH_M_tibia_R"),
        "fibula": dict(knee, mesh="VH_M_fibula_R"),
        "patella": dict(knee, mesh="VH_M_patella_R"),
        "skin": {"file": "VH_M_Skin.glb", "unit_scale": 1000.0, "source": SKIN_SOURCE},
    }
    axis = [MEDIAL_EPICONDYLE[i] - LATERAL_EPICONDYLE[i] for i in range(3)]
    # The quadriceps tendon and the graded tissues: rods up the front of the femur from the
    # patella's base (the femur's anterior surface is at z ~ 15 mm from y = -350 up).
    base = [PATELLA_BASE[0], PATELLA_BASE[1] - 4, PATELLA_BASE[2] - 3]
    t1, t2, t3 = [-134.0, -320.0, 27.0], [-131.0, -300.0, 28.0], [-130.0, -280.0, 29.0]
    fiber_up = [0.0, 1.0, 0.0]
    ligament_dir = [PATELLA_APEX[i] - TUBEROSITY[i] for i in range(3)]
    # Lines of action (per-element fiber fields): the quadriceps from the patella's base up the
    # front of the femur; the leg's muscles along the shank's and the thigh's axes (the centres of
    # the skin's sections at the cuts and at the joint line).
    quadriceps_path = [base, t1, t2, t3, [-126.0, JOINT_Y + CROP, 30.0]]
    leg_axis_path = [[-190.0, JOINT_Y - CROP, -70.0], [-150.0, JOINT_Y, -17.0], [-140.0, JOINT_Y + CROP, 0.0]]
    leg_parts = [
        {"region": "tibia", "solid": {"intersection": [
            {"union": [surface("tibia"), surface("fibula")]},
            {"half_space": {"point": [0, JOINT_Y - CROP, 0], "normal": [0, -1, 0]}}]}},
        {"region": "patella", "solid": {"offset": {"surfaces": ["patella"], "distance": CARTILAGE}}},
        {"region": "ligament", "solid": inside(capsule(lerp(PATELLA_APEX, PATELLA_BASE, 0.15), lerp(TUBEROSITY, PATELLA_APEX, 0.05), 5.0))},
        {"region": "tendon", "solid": inside(capsule(base, t1, 7.0))},
        {"region": "graded_2", "solid": inside(capsule(t1, t2, 9.0))},
        {"region": "graded_1", "solid": inside(capsule(t2, t3, 11.0))},
        # The muscle stops at MUSCLE_BASE_Y (75 mm above the joint line) and keeps SLIDE from the tendon, on
        # which it slides; the skin-fat fills the rest of the layer's inside and slides on the
        # patella, the ligament and the tendon (sliding_sleeve).
        {"region": "muscle", "solid": {"difference": [inside({"intersection": [
            {"offset": {"surfaces": ["skin"], "distance": -SKIN_FAT}},
            {"half_space": {"point": [0, MUSCLE_BASE_Y, 0], "normal": [0, -1, 0]}}]}, pouch=True),
            tendon_gap(base, t1, gap_end)]}},
        {"region": "skin", "solid": {"difference": [inside(surface("skin"), pouch=True), sliding_sleeve(base, t1, gap_end)]}},
    ]
    fine = {"surfaces": ["patella", "femur"], "size": round(0.4 * h, 3), "grading": 0.3}
    # Finer elements where the flexing knee crushes tissue most: along the whole quadriceps tendon
    # into graded_2 (it wraps the trochlea), and across the back of the knee at the joint line
    # (the popliteal fold). Capsules, since neither place has a surface of the data.
    tendon_zone = {"capsule": {"a": base, "b": t2, "radius": 12.0}, "size": round(0.16 * h, 3), "grading": 0.3}
    popliteal_zone = {"capsule": {"a": [-185.0, JOINT_Y - 10, -48.0], "b": [-110.0, JOINT_Y - 10, -48.0], "radius": 18.0},
                      "size": round(0.25 * h, 3), "grading": 0.3}
    # The penalties hold the penetration under PENETRATION_TOLERANCE up to about 75 degrees; beyond,
    # the calf pressed into the thigh and the patella into the femur need stiffer ones, which the
    # adaptive penalty supplies step by step (docs/vh-knee.md). A tolerance of 0 keeps the plain penalties.
    contact = {"self_contact": True}
    if penetration_tolerance > 0:
        contact["enforcement"] = {"method": "adaptive-penalty", "penetration_tolerance": penetration_tolerance}
    contact["pairs"] = [{"bodies": ["femur", "leg"], "penalty": FEMUR_PENALTY},
                        {"bodies": ["leg", "leg"], "penalty": LEG_PENALTY}]
    return {
        "name": "vh-knee-flexion",
        "description": "The seed's knee flexion on the Visible Human Male's right knee and skin (HRA 3D reference organs), "
                       "meshed from the surfaces (scripts/make_vh_knee.py, docs/vh-knee.md): rigid femur fixed, rigid "
                       "tibia and fibula turned 150 degrees about the epicondylar axis in 3-degree increments, rigid "
                       "patella free, held by the patellar ligament and the quadriceps tendon; Table 2's graded tissues; "
                       f"the thigh's muscle in {muscle_law}; skin-fat bonded to the tibia and the muscle. Frictionless material-depth contact "
                       "between every pair of parts and self-contact of the skin.",
        "units": "mm, mN, kPa",
        "data_dir": "../../shared/data/vh-knee",
        "materials": {
            "tendon": {"law": "veronda-westmann", "alpha": 1400.0, "beta": 8.0, "a": 1000.0,
                       "fiber": {"alpha": 500.0, "beta": 2.0, "direction": fiber_up}},
            "graded_2": {"law": "veronda-westmann", "alpha": 350.0, "beta": 8.0, "a": 500.0,
                         "fiber": {"alpha": 150.0, "beta": 2.0, "direction": fiber_up}},
            "graded_1": {"law": "veronda-westmann", "alpha": 14.0, "beta": 8.0, "a": 200.0,
                         "fiber": {"alpha": 20.0, "beta": 2.0, "direction": fiber_up}},
            "muscle": MUSCLE_LAWS[muscle_law],
            "skin": {"law": "mooney-rivlin", "C1": 5.0, "C2": 1.0, "a": 50.0},
        },
        "bodies": [
            {"name": "femur",
             "mesh": {"surfaces": {"element_size": h, "facet_distance": round(h / 30, 4), "surfaces": {"femur": surfaces["femur"]},
                                   "parts": [{"region": "femur", "solid": {"intersection": [
                                       surface("femur"), {"half_space": {"point": [0, JOINT_Y + CROP, 0], "normal": [0, 1, 0]}}]}}],
                                   "size_zones": [{"surfaces": ["femur"], "size": fine["size"], "grading": 0.3}]}},
             "regions": {"femur": {"rigid": "fixed", "contact_penalty_scale": STIFF_SCALE}},
             "contact": {"exclude_faces": [cut_plane(JOINT_Y + CROP, h)]}},
            {"name": "leg",
             "mesh": {"surfaces": {"element_size": h, "facet_distance": round(h / 30, 4), "surfaces": surfaces,
                                   "parts": leg_parts, "size_zones": [fine, tendon_zone, popliteal_zone]}},
             "regions": {
                 "tibia": {"rigid": {"prescribed": {"rotation": {"axis": axis, "point": LATERAL_EPICONDYLE, "angle_deg": angle_deg}}},
                           "contact_penalty_scale": STIFF_SCALE},
                 "patella": {"rigid": "free", "contact_penalty_scale": STIFF_SCALE},
                 "ligament": {"material": "tendon", "fiber_direction": ligament_dir, "contact_penalty_scale": STIFF_SCALE},
                 "tendon": {"material": "tendon", "fiber_path": quadriceps_path, "contact_penalty_scale": STIFF_SCALE},
                 "graded_2": {"material": "graded_2", "fiber_path": quadriceps_path},
                 "graded_1": {"material": "graded_1", "fiber_path": quadriceps_path},
                 "muscle": dict({"material": "muscle"}, **({"fiber_path": leg_axis_path} if "fiber" in MUSCLE_LAWS[muscle_law] else {})),
                 "skin": {"material": "skin"}},
             "contact": {"exclude_faces": [cut_plane(JOINT_Y + CROP, h), cut_plane(JOINT_Y - CROP, h)]}},
        ],
        "boundary_conditions": [
            {"name": "thigh_cut", "type": "planar", "normal": [0, 1, 0],
             "nodes": {"body": "leg", "plane": {"point": [0, JOINT_Y + CROP, 0], "normal": [0, 1, 0], "tolerance": round(h / 10, 3)}}},
        ],
        "contact": contact,
        "solver": {"increments": increments},
        "output": {"vtu": True},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--element-size", type=float, default=22.0,
                        help="mm; 22 gives about the seed's size (11.6k nodes, 46k tets)")
    parser.add_argument("--muscle-law", choices=sorted(MUSCLE_LAWS), default="mooney-rivlin",
                        help="the muscle's law: mooney-rivlin (the paper's pictures) or Table 2's veronda-westmann")
    parser.add_argument("--penetration-tolerance", type=float, default=PENETRATION_TOLERANCE,
                        help="mm; the adaptive penalty grows a pair's penalty while it penetrates deeper (0: plain penalties)")
    parser.add_argument("--tibiofemoral-space", type=float, default=TF_CAVITY,
                        help="mm; reach of the tibiofemoral joint space kept free of soft tissue")
    parser.add_argument("--tendon-gap-end", choices=["round", "flat"], default="round",
                        help="how the soft tissue's sliding gap round the quadriceps tendon ends at the tendon's top")
    parser.add_argument("--increments", type=int, default=50)
    parser.add_argument("--angle", type=float, default=150.0, help="final knee flexion (degrees)")
    parser.add_argument("--out", default=str(pathlib.Path(__file__).resolve().parent.parent / "examples" / "vh-knee-flexion.json"))
    args = parser.parse_args()
    pathlib.Path(args.out).write_text(json.dumps(scene(
        args.element_size, args.increments, args.angle, args.muscle_law, args.penetration_tolerance,
        args.tibiofemoral_space, args.tendon_gap_end), indent=1) + "\n")


if __name__ == "__main__":
    main()
