#!/usr/bin/env python3
"""Renders a knee-flexion run (examples/knee-flexion.json) as PNG.

Usage: /usr/bin/python3 scripts/render_knee.py OUTPUT_DIR [--angles 0 50 100 150] [--flexion 150]
                                               [--out DIR] [--vh] [--fold-window A0 A1 U0 U1]

--vh: a run of examples/vh-knee-flexion.json (the data's frame: looked at along x, the epicondylar
axis, +z anterior to the right, +y up; the section is the plane x = -148 mm through the patella).

Writes into DIR (default OUTPUT_DIR):
  knee_side.png      the leg's surface from the side (looking along the flexion axis) at the
                     increments closest to the given angles; skin translucent grey over the parts
  knee_cutaway.png   the section through the leg's mid-plane (y = 0) at the last increment,
                     coloured by material depth (the seed's Figs. 42-46); rigid parts in grey
  knee_fold.png      a close-up of that section behind the knee, where the skin folds onto itself,
                     with the contact pressure
  knee_rest.png      the same section at rest (the first increment), coloured by region: which
                     tissue fills the leg where, and where it is empty (white)
Orthographic projection with the painter's algorithm (matplotlib only, no OpenGL). Needs
Debian's python3-matplotlib, python3-numpy and python3-meshio.
"""
import argparse
import pathlib
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

# The generated leg's regions: femur, tibia, patella, ligament, tendon, graded_2, graded_1, muscle,
# skin (scripts/make_knee.py, whose docstring names these colours).
REGION_COLOURS = ["#b0b0b0", "#d9d9d9", "#5a8dd6", "#2f5fb3", "#2f5fb3", "#c25cc2", "#5cb85c", "#e6c229",
                  "#f2c9a0"]
SKIN_SIDE_COLOUR = "#b0b0b0"  # the side view's translucent skin
# The regions of both legs, in this order (knee_rest.png's legend).
REGION_NAMES = ["femur", "tibia", "patella", "ligament", "tendon", "graded_2", "graded_1", "muscle", "skin-fat"]
# The VH leg's regions: femur, tibia, patella, ligament, tendon, graded_2, graded_1, muscle, skin
# (scripts/make_vh_knee.py).
VH_REGION_COLOURS = ["#b0b0b0", "#d9d9d9", "#a0a0a0", "#2f5fb3", "#2f5fb3", "#c25cc2", "#5cb85c", "#d98c6a",
                     "#f2c9a0"]


class Frame:
    """Which coordinates the pictures show: the side view looks along `depth` (far side first) and
    plots (`across`, `up`); the section is the plane coordinate[`section_axis`] = `section_at`."""

    def __init__(self, depth, across, up, section_axis, section_at, fold_window, labels):
        self.depth, self.across, self.up = depth, across, up
        self.section_axis, self.section_at = section_axis, section_at
        self.fold_window, self.labels = fold_window, labels


# The generated leg: flexion axis y, x anterior, z up; a section just off the symmetry plane,
# where generated meshes put whole layers of nodes.
GENERATED = Frame(1, 0, 2, 1, 0.37, (-110, 5, 5, 125), ("x (mm, anterior)", "z (mm)"))
# The VH knee: flexion axis ~x, z anterior, y up; the section through the patella.
VH = Frame(0, 2, 1, 0, -148.0, (-200, -40, -470, -330), ("z (mm, anterior)", "y (mm, up)"))
FRAME = GENERATED


def read_series(directory):
    root = ET.parse(directory / "sinew.pvd").getroot()
    return [(float(d.get("timestep")), directory / d.get("file")) for d in root.iter("DataSet")]


def boundary_faces(tets):
    """Boundary triangles (outward winding for positively oriented tets) and their tets."""
    faces = np.concatenate([tets[:, [0, 2, 1]], tets[:, [0, 1, 3]], tets[:, [1, 2, 3]], tets[:, [0, 3, 2]]])
    owner = np.tile(np.arange(len(tets)), 4)
    key = np.sort(faces, axis=1)
    _, index, counts = np.unique(key, axis=0, return_index=True, return_counts=True)
    keep = index[counts == 1]
    return faces[keep], owner[keep]


def shade(points, faces, light=np.array([0.3, -1.0, 0.5])):
    n = np.cross(points[faces[:, 1]] - points[faces[:, 0]], points[faces[:, 2]] - points[faces[:, 0]])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    light = light / np.linalg.norm(light)
    return 0.35 + 0.65 * np.abs(n @ light)


def draw_side(ax, mesh, title):
    """The surface seen from -y (the side), x to the right, z up; skin translucent."""
    p = mesh.points
    tets = mesh.cells_dict["tetra"]
    region = np.asarray(mesh.cell_data_dict["region"]["tetra"]).reshape(-1).astype(int)
    faces, owner = boundary_faces(tets)
    skin_region = region.max()  # the skin is the last region of the leg
    depth = p[faces].mean(axis=1)[:, FRAME.depth]
    order = np.argsort(-depth)  # far (large depth coordinate) first
    faces, owner = faces[order], owner[order]
    light = shade(p, faces)
    colours = []
    for f, t, s in zip(faces, owner, light):
        r = region[t]
        colour = SKIN_SIDE_COLOUR if r == skin_region else REGION_COLOURS[r % len(REGION_COLOURS)]
        base = np.array(matplotlib.colors.to_rgb(colour))
        alpha = 0.35 if r == skin_region else 1.0
        colours.append((*(base * s), alpha))
    ax.add_collection(PolyCollection(p[faces][:, :, [FRAME.across, FRAME.up]], facecolors=colours, edgecolors="none"))
    ax.set_xlim(p[:, FRAME.across].min() - 10, p[:, FRAME.across].max() + 10)
    ax.set_ylim(p[:, FRAME.up].min() - 10, p[:, FRAME.up].max() + 10)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=9)
    ax.axis("off")


def section(mesh, field):
    """Polygons of the tets cut by the frame's section plane, with the mean of `field` on each."""
    p = mesh.points.copy()
    a = FRAME.section_axis
    p[:, a] -= FRAME.section_at
    tets = mesh.cells_dict["tetra"]
    y = p[tets][:, :, a]
    cut = (y.min(axis=1) < 0) & (y.max(axis=1) > 0)
    polys, values, owners = [], [], []
    f = mesh.point_data[field] if field in mesh.point_data else np.zeros(len(p))
    if f.ndim > 1:
        f = np.linalg.norm(f, axis=1)
    for t in np.nonzero(cut)[0]:
        v = tets[t]
        pts = []
        vals = []
        for a in range(4):
            for b in range(a + 1, 4):
                ya, yb = p[v[a], FRAME.section_axis], p[v[b], FRAME.section_axis]
                if (ya < 0) != (yb < 0):
                    s = ya / (ya - yb)
                    q = p[v[a]] + s * (p[v[b]] - p[v[a]])
                    pts.append([q[FRAME.across], q[FRAME.up]])
                    vals.append(f[v[a]] + s * (f[v[b]] - f[v[a]]))
        pts = np.array(pts)
        c = pts.mean(axis=0)
        angle = np.arctan2(pts[:, 1] - c[1], pts[:, 0] - c[0])
        polys.append(pts[np.argsort(angle)])
        values.append(np.mean(vals))
        owners.append(t)
    return polys, np.array(values), np.array(owners, dtype=int)


def draw_section(ax, mesh, field, label, window=None, cmap="turbo_r"):
    polys, values, owners = section(mesh, field)
    rigid = np.asarray(mesh.cell_data_dict["rigid"]["tetra"]).reshape(-1)[owners] == 1
    soft = [q for q, r in zip(polys, rigid) if not r]
    hard = [q for q, r in zip(polys, rigid) if r]
    ax.add_collection(PolyCollection(hard, facecolors="#9a9a9a", edgecolors="#707070", linewidths=0.1))
    pc = PolyCollection(soft, array=values[~rigid], cmap=cmap, edgecolors="k", linewidths=0.08)
    if window is not None:  # colour scale from what the window shows (a far-off peak would wash it out)
        centres = np.array([q.mean(axis=0) for q in soft])
        inside = ((centres[:, 0] > window[0]) & (centres[:, 0] < window[1]) & (centres[:, 1] > window[2]) &
                  (centres[:, 1] < window[3]))
        if inside.any() and values[~rigid][inside].max() > 0:
            shown = values[~rigid][inside]
            pc.set_clim(0, np.percentile(shown[shown > 0], 98) if (shown > 0).any() else 1)
    ax.add_collection(pc)
    plt.colorbar(pc, ax=ax, shrink=0.7, label=label)
    frame_section(ax, polys, window)


def frame_section(ax, polys, window=None):
    """Limits (`window`, or the polygons with a 5 mm margin), equal aspect and axis labels."""
    allp = np.concatenate(polys)
    if window is None:
        window = (allp[:, 0].min() - 5, allp[:, 0].max() + 5, allp[:, 1].min() - 5, allp[:, 1].max() + 5)
    ax.set_xlim(window[0], window[1])
    ax.set_ylim(window[2], window[3])
    ax.set_aspect("equal")
    ax.set_xlabel(FRAME.labels[0])
    ax.set_ylabel(FRAME.labels[1])


def draw_regions(ax, mesh):
    """The frame's section coloured by region (rigid parts too), with a legend of the regions cut."""
    polys, _, owners = section(mesh, "material_depth")
    region = np.asarray(mesh.cell_data_dict["region"]["tetra"]).reshape(-1).astype(int)[owners]
    colours = [REGION_COLOURS[r % len(REGION_COLOURS)] for r in region]
    ax.add_collection(PolyCollection(polys, facecolors=colours, edgecolors="k", linewidths=0.08))
    for r in sorted(set(region)):
        ax.plot([], [], "s", color=REGION_COLOURS[r % len(REGION_COLOURS)], markersize=8,
                label=REGION_NAMES[r] if r < len(REGION_NAMES) else f"region {r}")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8, frameon=False)
    frame_section(ax, polys)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("--angles", type=float, nargs="*", default=[0, 50, 100, 150])
    parser.add_argument("--flexion", type=float, default=150.0, help="flexion angle at lambda = 1 (degrees)")
    parser.add_argument("--out")
    parser.add_argument("--vh", action="store_true", help="a run of examples/vh-knee-flexion.json")
    parser.add_argument("--fold-window", type=float, nargs=4, metavar=("A0", "A1", "U0", "U1"),
                        help="the close-up's window in the picture's coordinates (across, up; mm)")
    args = parser.parse_args()
    global FRAME, REGION_COLOURS
    FRAME = VH if args.vh else GENERATED
    if args.vh:
        REGION_COLOURS = VH_REGION_COLOURS
    directory = pathlib.Path(args.directory)
    out = pathlib.Path(args.out) if args.out else directory
    out.mkdir(parents=True, exist_ok=True)
    series = read_series(directory)
    lambdas = np.array([t for t, _ in series])

    picks = []
    for angle in args.angles:
        k = int(np.argmin(np.abs(lambdas * args.flexion - angle)))
        if k not in picks:
            picks.append(k)
    fig, axes = plt.subplots(1, len(picks), figsize=(3.6 * len(picks), 5.2), squeeze=False)
    for ax, k in zip(axes[0], picks):
        draw_side(ax, meshio.read(series[k][1]), f"{lambdas[k] * args.flexion:.0f}° flexion")
    fig.tight_layout()
    fig.savefig(out / "knee_side.png", dpi=110)
    plt.close(fig)

    last = meshio.read(series[-1][1])
    angle = lambdas[-1] * args.flexion
    fig, ax = plt.subplots(figsize=(7.5, 7))
    draw_section(ax, last, "material_depth", "material depth (mm)")
    ax.set_title(f"section at {angle:.0f}° flexion, coloured by material depth (rigid parts grey)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out / "knee_cutaway.png", dpi=110)
    plt.close(fig)

    # Behind the knee: the posterior crease, where the skin-fat of the calf folds onto the thigh's.
    fig, ax = plt.subplots(figsize=(7.5, 6))
    window = tuple(args.fold_window) if args.fold_window else FRAME.fold_window
    draw_section(ax, last, "contact_pressure", "contact pressure (kPa)", window=window, cmap="viridis")
    ax.set_title(f"behind the knee at {angle:.0f}° flexion: section, contact pressure", fontsize=9)
    fig.tight_layout()
    fig.savefig(out / "knee_fold.png", dpi=110)
    plt.close(fig)
    fig, ax = plt.subplots(figsize=(7.5, 7))
    draw_regions(ax, meshio.read(series[0][1]))
    ax.set_title(f"section at rest ({lambdas[0] * args.flexion:.0f}° flexion), coloured by region", fontsize=9)
    fig.tight_layout()
    fig.savefig(out / "knee_rest.png", dpi=110)
    plt.close(fig)
    print(f"wrote knee_side.png ({', '.join(f'{lambdas[k] * args.flexion:.0f}°' for k in picks)}), "
          f"knee_cutaway.png, knee_fold.png and knee_rest.png to {out}")


if __name__ == "__main__":
    main()
