#!/usr/bin/env python3
"""Renders frames of a sinew run (the .pvd series in an output directory) as PNG.

Usage: /usr/bin/python3 scripts/render_frames.py OUTPUT_DIR [--times T ...] [--impact COLUMN]
                                                   [--elev 15] [--azim -70] [--out PREFIX]
Without --times: the first frame, the first frame at or after the first step where the steps.csv
column given by --impact is non-zero (default: the first column named contact.*.fz), and the
last frame. Writes PREFIX_<k>.png per frame and PREFIX.png with all frames side by side
(PREFIX defaults to OUTPUT_DIR/frames). Needs Debian's python3-matplotlib and python3-meshio.
"""
import argparse
import csv
import pathlib
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_series(directory):
    root = ET.parse(directory / "sinew.pvd").getroot()
    return [(float(d.get("timestep")), directory / d.get("file")) for d in root.iter("DataSet")]


def boundary_faces(tets):
    faces = np.concatenate([tets[:, [0, 2, 1]], tets[:, [0, 1, 3]], tets[:, [1, 2, 3]], tets[:, [0, 3, 2]]])
    key = np.sort(faces, axis=1)
    _, index, counts = np.unique(key, axis=0, return_index=True, return_counts=True)
    return faces[index[counts == 1]]


def pick_times(series, directory, impact_column):
    times = [t for t, _ in series]
    chosen = [times[0]]
    steps_path = directory / "steps.csv"
    if steps_path.exists():
        rows = list(csv.DictReader(open(steps_path)))
        if rows:
            column = impact_column or next((c for c in rows[0] if c.startswith("contact.") and c.endswith(".fz")), None)
            if column:
                hit = next((float(r["time"]) for r in rows if abs(float(r[column])) > 0), None)
                if hit is not None:
                    chosen.append(min((t for t in times if t >= hit), default=times[-1]))
    chosen.append(times[-1])
    return sorted(set(chosen))


def draw(ax, path, elev, azim, limits):
    mesh = meshio.read(path)
    tets = mesh.cells_dict["tetra"]
    region = mesh.cell_data_dict.get("region", {}).get("tetra")
    faces = boundary_faces(tets)
    points = mesh.points
    # Colour per face by the region of a tet that owns it (looked up through the face's nodes).
    colors = None
    if region is not None:
        owner = {}
        for t, tet in enumerate(tets):
            for f in ((0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)):
                owner[tuple(sorted(tet[list(f)]))] = region[t]
        cmap = plt.get_cmap("tab10")
        colors = [cmap(int(owner[tuple(sorted(f))]) % 10) for f in faces]
    polygons = points[faces]
    collection = Poly3DCollection(polygons, facecolors=colors or "lightsteelblue", edgecolors="k", linewidths=0.05)
    ax.add_collection3d(collection)
    for axis, (lo, hi) in zip("xyz", limits):
        getattr(ax, f"set_{axis}lim")(lo, hi)
    ax.set_box_aspect([hi - lo for lo, hi in limits])
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", type=pathlib.Path)
    parser.add_argument("--times", type=float, nargs="*")
    parser.add_argument("--impact")
    parser.add_argument("--elev", type=float, default=15)
    parser.add_argument("--azim", type=float, default=-70)
    parser.add_argument("--out")
    args = parser.parse_args()
    series = read_series(args.directory)
    times = args.times or pick_times(series, args.directory, args.impact)
    frames = [min(series, key=lambda s: abs(s[0] - t)) for t in times]
    points = meshio.read(frames[0][1]).points
    lo, hi = points.min(axis=0), points.max(axis=0)
    limits = list(zip(lo, hi))
    prefix = pathlib.Path(args.out) if args.out else args.directory / "frames"
    figure = plt.figure(figsize=(5 * len(frames), 5))
    for k, (t, path) in enumerate(frames):
        ax = figure.add_subplot(1, len(frames), k + 1, projection="3d")
        draw(ax, path, args.elev, args.azim, limits)
        ax.set_title(f"t = {t:.3g}")
        single = plt.figure(figsize=(6, 6))
        draw(single.add_subplot(projection="3d"), path, args.elev, args.azim, limits)
        single.suptitle(f"t = {t:.3g}")
        single.savefig(f"{prefix}_{k}.png", dpi=110, bbox_inches="tight")
        plt.close(single)
    figure.savefig(f"{prefix}.png", dpi=110, bbox_inches="tight")
    print(f"wrote {prefix}.png and {len(frames)} single frames (t = {', '.join(f'{t:.3g}' for t, _ in frames)})")


if __name__ == "__main__":
    main()
