#!/usr/bin/env python3
"""Plots a `sinew study convergence` directory (dissertation section 6.5, Figs. 29-35).

Usage: /usr/bin/python3 scripts/plot_convergence_study.py STUDY_DIR [--out DIR]

Writes into DIR (default STUDY_DIR):
  convergence_eps<P>.png   equilibrium residual of every Newton iteration against the total
                           iteration count, both methods, one plot per penalty (Figs. 31-34)
  convergence_all.png      all of them in one plot (Fig. 35)
  force_sweep.png          (with a sweep) contact forces on the swept body's nodes at five
                           positions, one row per method (Figs. 29-30)
  force_sweep_totals.png   (with a sweep) the total contact force on the swept body against the
                           offset, both methods: continuous for area integration, jumps for point
                           collocation
Needs Debian's python3-matplotlib, python3-numpy and python3-meshio.
"""
import argparse
import csv
import json
import pathlib
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STYLE = {"area": {"color": "tab:blue", "label": "area integration"},
         "point": {"color": "tab:red", "label": "point collocation"}}


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def residual_series(rows):
    """{(method, penalty): (total_iteration array, equilibrium residual array)}"""
    series = {}
    for r in rows:
        key = (r["method"], float(r["penalty"]))
        it, res = series.setdefault(key, ([], []))
        it.append(int(r["total_iteration"]))
        res.append(float(r["equilibrium_residual"]))
    return {k: (np.array(v[0]), np.array(v[1])) for k, v in series.items()}


def positive(values):
    """Residuals of exactly 0 cannot be drawn on a log axis: show them at the axis floor."""
    floor = 1e-300
    return np.maximum(values, floor)


def plot_residuals(series, runs, out):
    penalties = sorted({p for _, p in series if p > 0})
    for p in penalties:
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for method in ("area", "point"):
            if (method, p) not in series:
                continue
            it, res = series[(method, p)]
            run = runs.get((method, p), {})
            status = "converged" if run.get("converged") == "1" else (
                "not converged" if run.get("solved") == "1" else "failed")
            ax.semilogy(it, positive(res), color=STYLE[method]["color"], lw=0.9,
                        label=f"{STYLE[method]['label']} ({status})")
        ax.set_xlabel("Newton iterations from the start")
        ax.set_ylabel("equilibrium residual |f| (N)")
        ax.set_title(f"penalty ε = {p:g}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(out / f"convergence_eps{p:g}.png", dpi=120)
        plt.close(fig)
    fig, ax = plt.subplots(figsize=(7.5, 5))
    shades = np.linspace(0.35, 1.0, max(1, len(penalties)))
    for method, marker in (("area", "-"), ("point", "--")):
        cmap = plt.get_cmap("Blues" if method == "area" else "Reds")
        for shade, p in zip(shades, penalties):
            if (method, p) not in series:
                continue
            it, res = series[(method, p)]
            ax.semilogy(it, positive(res), marker, color=cmap(shade), lw=0.9,
                        label=f"{STYLE[method]['label']}, ε = {p:g}")
    ax.set_xlabel("Newton iterations from the start")
    ax.set_ylabel("equilibrium residual |f| (N)")
    ax.set_title("all penalties (dissertation Fig. 35)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out / "convergence_all.png", dpi=120)
    plt.close(fig)


def first_vtu(study):
    """The rest configuration: the first VTU of the first run that wrote one."""
    for pvd in sorted(study.glob("*/sinew.pvd")):
        data = [d.get("file") for d in ET.parse(pvd).getroot().iter("DataSet")]
        if data:
            return pvd.parent / data[0]
    return None


def front_edges(points, tets, axis_normal):
    """Boundary edges of the faces that look along -axis_normal (the slab's front face)."""
    faces = np.concatenate([tets[:, [0, 2, 1]], tets[:, [0, 1, 3]], tets[:, [1, 2, 3]], tets[:, [0, 3, 2]]])
    key = np.sort(faces, axis=1)
    _, index, counts = np.unique(key, axis=0, return_index=True, return_counts=True)
    boundary = faces[index[counts == 1]]
    low = points[:, axis_normal].min()
    front = boundary[np.all(np.abs(points[boundary][:, :, axis_normal] - low) < 1e-9, axis=1)]
    edges = np.concatenate([front[:, [0, 1]], front[:, [1, 2]], front[:, [2, 0]]])
    return np.unique(np.sort(edges, axis=1), axis=0)


def plot_sweep(study, out):
    import meshio

    meta = json.loads((study / "sweep.json").read_text())
    forces = read_rows(study / "sweep_forces.csv")
    totals = read_rows(study / "sweep_totals.csv")
    vtu = first_vtu(study)
    mesh = meshio.read(vtu) if vtu else None
    translation = np.array(meta["translation"])
    start = np.array(meta.get("from", [0.0, 0.0, 0.0]))
    methods = [m for m in ("area", "point") if any(r["method"] == m for r in totals)]
    n = int(meta["positions"])
    chosen = sorted({round(k) for k in np.linspace(0, n - 1, 5)})
    if mesh is not None:
        points = mesh.points
        extent = points.max(axis=0) - points.min(axis=0)
    else:
        points = None
        extent = np.ones(3)
    normal = int(np.argmin(extent))
    u, v = [a for a in range(3) if a != normal]
    names = "xyz"
    scale_all = max((np.hypot(float(r["f" + names[u]]), float(r["f" + names[v]])) for r in forces), default=1.0)
    fig, axes = plt.subplots(len(methods), len(chosen), figsize=(3.0 * len(chosen), 3.1 * len(methods)),
                             squeeze=False)
    first, count = int(meta["first_node"]), int(meta["num_nodes"])
    for row, method in enumerate(methods):
        for col, k in enumerate(chosen):
            ax = axes[row][col]
            s = k / (n - 1)
            if points is not None:
                moved = points.copy()
                moved[first:first + count] += start + s * translation
                tets = mesh.cells_dict["tetra"]
                for e in front_edges(moved, tets, normal):
                    inside = first <= e[0] < first + count
                    ax.plot(moved[e, u], moved[e, v], color="tab:orange" if inside else "0.55", lw=0.4)
            sel = [r for r in forces if r["method"] == method and int(r["position"]) == k]
            if sel:
                pu = np.array([float(r[names[u]]) for r in sel])
                pv = np.array([float(r[names[v]]) for r in sel])
                fu = np.array([float(r["f" + names[u]]) for r in sel])
                fv = np.array([float(r["f" + names[v]]) for r in sel])
                ax.quiver(pu, pv, fu, fv, color="red", angles="xy", scale_units="xy",
                          scale=scale_all / 1.5, width=0.008)
                ax.plot(pu, pv, "s", ms=2, color="gold", mec="k", mew=0.3)
            offset = float(next((r["offset"] for r in totals if r["method"] == method and int(r["position"]) == k),
                                0.0))
            ax.set_title(f"{STYLE[method]['label']}\nmoved {offset:.3g}", fontsize=8)
            ax.set_aspect("equal")
            c = points[first:first + count].min(axis=0) if points is not None else np.zeros(3)
            shift = start + s * translation
            ax.set_xlim(c[u] + shift[u] - 1.2, c[u] + shift[u] + 2.3)
            ax.set_ylim(c[v] + shift[v] - 1.2, c[v] + shift[v] + 2.3)
            ax.tick_params(labelsize=6)
    fig.suptitle(f"contact forces on '{meta['body']}' (yellow: its nodes with a force) as it moves by "
                 f"{np.round(translation, 3).tolist()} from rest + {np.round(start, 3).tolist()} "
                 f"(ε = {meta['penalty']:g}; arrows to one scale)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out / "force_sweep.png", dpi=100)
    plt.close(fig)

    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    for method in methods:
        rows = [r for r in totals if r["method"] == method]
        off = np.array([float(r["offset"]) for r in rows])
        for ax, comp in zip(axes, (names[u], names[v])):
            ax.plot(off, [float(r["f" + comp]) for r in rows], ".-", color=STYLE[method]["color"], lw=1, ms=3,
                    label=STYLE[method]["label"])
    for ax, comp in zip(axes, (names[u], names[v])):
        ax.set_xlabel(f"distance moved along {np.round(translation / np.linalg.norm(translation), 3).tolist()} "
                      f"from rest + {np.round(start, 3).tolist()}")
        ax.set_ylabel(f"total contact force f{comp} on '{meta['body']}' (N)")
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(out / "force_sweep_totals.png", dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("study")
    parser.add_argument("--out")
    args = parser.parse_args()
    study = pathlib.Path(args.study)
    out = pathlib.Path(args.out) if args.out else study
    out.mkdir(parents=True, exist_ok=True)
    runs = {(r["method"], float(r["penalty"])): r for r in read_rows(study / "runs.csv")}
    plot_residuals(residual_series(read_rows(study / "residuals.csv")), runs, out)
    written = ["convergence_eps*.png", "convergence_all.png"]
    if (study / "sweep.json").exists():
        plot_sweep(study, out)
        written += ["force_sweep.png", "force_sweep_totals.png"]
    print(f"wrote {', '.join(written)} to {out}")


if __name__ == "__main__":
    main()
