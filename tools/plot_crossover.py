#!/usr/bin/env python3
"""Plots of the crossover by screen size of `qacc compare SCENE --sizes ...` (docs/COMPARE.md).

    tools/plot_crossover.py DIR [DIR ...]

Reads DIR/crossover.json (one scene each) and writes DIR/crossover.{png,svg}: the facet-path
cycles over the quadric-path cycles on the same accelerator, at the accelerator's silhouette
error, against the mean projected primitive size (pixels the reference covers per quadric), one
point per image size (labelled), the break-even line (ratio 1) and the break-even size when the
ratio crosses it. The C++ writes the data; this script only draws it (Debian's python3-matplotlib).
"""
import json
import math
import os
import sys

from plot_common import num  # noqa: E402  (also selects matplotlib's Agg backend)
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FuncFormatter  # noqa: E402

PLAIN = FuncFormatter(lambda v, _: "%g" % v)  # 2, 0.5, 1000 rather than 2x10^0


def plot(d):
    with open(os.path.join(d, "crossover.json")) as f:
        c = json.load(f)
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=110)
    xs, ys, missing = [], [], []
    for s in c["sizes"]:
        x, y = num(s["px_per_primitive"]), num(s["cycle_ratio"])
        label = "%dx%d" % (s["width"], s["height"])
        if math.isfinite(y) and y > 0:
            xs.append(x)
            ys.append(y)
            mark = "" if s["status"] == "interpolated" else " (%s)" % s["status"].replace("_", " ")
            ax.annotate(label + mark, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
        else:
            missing.append(label)
    ax.plot(xs, ys, "o-", color="C0", label="facet cycles / quadric cycles at equal silhouette error")
    ax.axhline(1, color="gray", linestyle=":", linewidth=1)
    ax.text(0.01, 1, " break-even (ratio 1)", transform=ax.get_yaxis_transform(), va="bottom", fontsize=8,
            color="gray")
    be = c["break_even"]
    if be.get("found"):
        bx = num(be["px_per_primitive"])
        ax.axvline(bx, color="C3", linestyle="--", linewidth=1,
                   label="break-even: %.3g px per primitive (quadrics pay %s)" % (bx, be["quadrics_pay"]))
    else:
        ax.plot([], [], " ", label="break-even: not reached in the measured range")
    if missing:
        ax.plot([], [], " ", label="no ratio (not reached or no cycles): " + ", ".join(missing))
    ax.set_xscale("log")
    ax.set_yscale("log")
    if not xs:
        # No size has a ratio (the facets never reach the accelerator's silhouette error):
        # the axes still span the measured primitive sizes, and the plot says so.
        sizes = [num(s["px_per_primitive"]) for s in c["sizes"] if num(s["px_per_primitive"]) > 0]
        if sizes:
            ax.set_xlim(min(sizes) / 1.5, max(sizes) * 1.5)
        ax.set_ylim(0.1, 100)
        ax.text(0.5, 0.5, "no measured size reaches the accelerator's silhouette error\n(no ratio to plot)",
                transform=ax.transAxes, ha="center", va="center", fontsize=9, color="C3")
    for s in c["sizes"]:
        x, y = num(s["px_per_primitive"]), num(s["cycle_ratio"])
        if not (math.isfinite(y) and y > 0) and x > 0:
            ax.axvline(x, color="gray", linestyle=":", linewidth=0.8)
            ax.text(x, 0.02, " %dx%d: %s" % (s["width"], s["height"], s["status"].replace("_", " ")),
                    transform=ax.get_xaxis_transform(), rotation=90, fontsize=6, color="gray", va="bottom")
    # Plain numbers on both axes; the minor ticks labelled only on an axis that spans less
    # than a decade (else its major ticks say enough).
    for axis, lim in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        axis.set_major_formatter(PLAIN)
        narrow = lim[0] > 0 and lim[1] / lim[0] < 10
        axis.set_minor_formatter(PLAIN if narrow else FuncFormatter(lambda v, _: ""))
    ax.set_xlabel("mean projected primitive size (pixels covered per quadric primitive)")
    ax.set_ylabel("facet-path cycles / quadric-path cycles")
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=7, loc="best" if xs else "upper right")
    ax.set_title("%s: quadrics vs triangles on the accelerator by screen size\n(%s config, qacc %s)" %
                 (c["scene"], c["hw_config"], c["qacc_version"]), fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "crossover.png"))
    fig.savefig(os.path.join(d, "crossover.svg"))
    plt.close(fig)


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: plot_crossover.py DIR [DIR ...]")
    for d in sys.argv[1:]:
        plot(d)


if __name__ == "__main__":
    main()
