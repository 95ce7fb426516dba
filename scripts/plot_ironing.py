#!/usr/bin/env python3
"""Plots the die's reactions in an ironing run (examples/ironing.json) against the slide.

Usage: /usr/bin/python3 scripts/plot_ironing.py OUTPUT_DIR [--press 0.25] [--slide 4.0] [--mu 0.3]
                                                [--out FILE]

Left: the die's vertical reaction (|die_z.fz|), its horizontal reaction (die_x.fx) and the friction
force on the slab from the die (contact.slab.die.friction_fx). Right: the friction force over the
normal contact force, and the die's horizontal over vertical reaction, against mu. The slide is
4.0 (lambda - press) / (1 - press) once the die is pressed. Writes OUTPUT_DIR/ironing.png (or FILE)
and prints the ratios in steady sliding (the second half of the slide).
"""
import argparse
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("--press", type=float, default=0.25)
    parser.add_argument("--slide", type=float, default=4.0)
    parser.add_argument("--mu", type=float, default=0.3)
    parser.add_argument("--out")
    args = parser.parse_args()
    rows = list(csv.DictReader(open(pathlib.Path(args.output) / "steps.csv")))
    col = lambda name: np.array([float(r[name]) for r in rows])  # noqa: E731
    lam = col("lambda")
    slide = np.clip((lam - args.press) / (1 - args.press), 0, None) * args.slide
    normal = -col("die_z.fz")
    tangential = col("die_x.fx")
    friction = col("contact.slab.die.friction_fx")
    contact_normal = -col("contact.slab.die.fz")
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    a.plot(slide, normal, "o-", ms=3, label="die, vertical reaction")
    a.plot(slide, tangential, "s-", ms=3, label="die, horizontal reaction")
    a.plot(slide, friction, "^-", ms=3, label="friction force (slab from die)")
    a.set_xlabel("slide (mm)")
    a.set_ylabel("force (N)")
    a.legend()
    a.grid(alpha=0.3)
    sliding = lam > args.press
    b.plot(slide[sliding], (friction / contact_normal)[sliding], "^-", ms=3, label="friction / normal contact force")
    b.plot(slide[sliding], (tangential / normal)[sliding], "s-", ms=3, label="die: horizontal / vertical reaction")
    b.axhline(args.mu, color="k", lw=1, ls="--", label=f"mu = {args.mu}")
    b.set_xlabel("slide (mm)")
    b.set_ylabel("ratio")
    b.set_ylim(0, 2 * args.mu)
    b.legend()
    b.grid(alpha=0.3)
    fig.suptitle("Ironing (Puso and Laursen 2004): die reactions against the slide")
    fig.tight_layout()
    out = args.out or str(pathlib.Path(args.output) / "ironing.png")
    fig.savefig(out, dpi=110)
    steady = slide > args.slide / 2
    print(f"steady sliding (slide > {args.slide / 2}): friction / normal contact force "
          f"{np.mean((friction / contact_normal)[steady]):.4f}, die horizontal / vertical reaction "
          f"{np.mean((tangential / normal)[steady]):.4f} (mu = {args.mu}); wrote {out}")


if __name__ == "__main__":
    main()
