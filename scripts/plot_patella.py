#!/usr/bin/env python3
"""Plots the patella's path in a knee-flexion run against the knee's flexion (rigid_bodies.csv).

Usage: /usr/bin/python3 scripts/plot_patella.py OUTPUT_DIR [--axis X Y Z] [--up X Y Z] [--anterior X Y Z]
                                                [--out FILE]

The knee's flexion is the tibia's rotation about the flexion axis (--axis, the direction the scene
turns the tibia about); the patella's flexion is its rotation about the same axis (the projection of
its rotation vector). Its translation is split into proximal (--up) and anterior (--anterior)
components. Defaults: the VH knee (examples/vh-knee-flexion.json: the epicondylar axis, +y up, +z
anterior). For the generated knee: --axis 0 1 0 --up 0 0 1 --anterior 1 0 0.

The shaded band is the in-vivo relation of the review cited in docs/vh-knee.md: the patella's flexion
lags the knee's by 30-40 %, so it is 0.6-0.7 times the knee's flexion.
Writes OUTPUT_DIR/patella_tracking.png (or FILE) and prints the path every 15 degrees.
"""
import argparse
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

VH_AXIS = [85.02, -8.36, -0.94]  # medial minus lateral epicondyle (scripts/make_vh_knee.py)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("--axis", type=float, nargs=3, default=VH_AXIS)
    parser.add_argument("--up", type=float, nargs=3, default=[0, 1, 0])
    parser.add_argument("--anterior", type=float, nargs=3, default=[0, 0, 1])
    parser.add_argument("--out")
    args = parser.parse_args()
    directory = pathlib.Path(args.directory)
    rows = list(csv.DictReader(open(directory / "rigid_bodies.csv")))
    axis = np.array(args.axis) / np.linalg.norm(args.axis)
    up, anterior = np.array(args.up, float), np.array(args.anterior, float)

    def vec(row, body, keys):
        return np.array([float(row[f"{body}.{k}"]) for k in keys])

    knee = np.degrees([vec(r, "leg/tibia", ["rx", "ry", "rz"]) @ axis for r in rows])
    patella_flexion = np.degrees([vec(r, "leg/patella", ["rx", "ry", "rz"]) @ axis for r in rows])
    position = np.array([vec(r, "leg/patella", ["x", "y", "z"]) for r in rows])
    start = position[0]
    if abs(knee[0]) > 1e-9:  # the first row is the first converged increment: extrapolate the rest state
        start = position[0] - (position[1] - position[0]) * knee[0] / (knee[1] - knee[0])
    proximal = (position - start) @ up
    forward = (position - start) @ anterior
    knee = np.concatenate([[0.0], knee])
    patella_flexion = np.concatenate([[0.0], patella_flexion])
    proximal = np.concatenate([[0.0], proximal])
    forward = np.concatenate([[0.0], forward])

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.4))
    a1.fill_between(knee, 0.6 * knee, 0.7 * knee, color="#c8dcf0", label="in vivo: 0.6-0.7 x knee flexion")
    a1.plot(knee, patella_flexion, "o-", ms=3, color="#1f4e9c", label="sinew: patellar flexion")
    a1.set_xlabel("knee flexion (deg)")
    a1.set_ylabel("patellar flexion (deg)")
    a1.legend(loc="upper left", fontsize=8)
    a1.grid(alpha=0.3)
    a2.plot(knee, -proximal, "o-", ms=3, label="distal translation")
    a2.plot(knee, -forward, "s-", ms=3, label="posterior translation")
    a2.set_xlabel("knee flexion (deg)")
    a2.set_ylabel("patella displacement (mm)")
    a2.legend(loc="upper left", fontsize=8)
    a2.grid(alpha=0.3)
    fig.suptitle("patella in the femoral groove", fontsize=10)
    fig.tight_layout()
    out = pathlib.Path(args.out) if args.out else directory / "patella_tracking.png"
    fig.savefig(out, dpi=110)
    for k in range(len(knee)):
        if k == len(knee) - 1 or abs(knee[k] / 15 - round(knee[k] / 15)) < 1e-6:
            print(f"knee {knee[k]:6.1f} deg: patella flexion {patella_flexion[k]:6.1f} deg "
                  f"({patella_flexion[k] / knee[k] if knee[k] else 0:.2f} x), distal {-proximal[k]:6.1f} mm, "
                  f"posterior {-forward[k]:6.1f} mm")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
