#!/usr/bin/env python3
"""Composes the labelled side-by-side figure of a `qacc compare` output directory (docs/COMPARE.md).

    tools/compose_side_by_side.py DIR

Reads DIR/side_by_side.json and the panels it names (written by `qacc compare`, which runs this
script itself) and writes DIR/side_by_side.png: top, the reference | the accelerator (its
configuration, cycles) | the triangles (their count and tolerance); bottom, the luma-error maps of
the accelerator and of the triangles with a colour scale and their PSNR | the triangles' coverage
errors with a legend. Every panel is titled in the image. The C++ writes the data; this script
only draws it (Debian's python3-matplotlib).
"""
import json
import math
import os
import sys

from plot_common import num  # noqa: E402  (also selects matplotlib's Agg backend)
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402


def db(v):
    v = num(v)
    return "inf (identical)" if math.isinf(v) else "%.1f dB" % v


def thousands(n):
    return "{:,}".format(int(n)).replace(",", " ")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: compose_side_by_side.py DIR")
    d = sys.argv[1]
    with open(os.path.join(d, "side_by_side.json")) as f:
        info = json.load(f)
    w, h = info["width"], info["height"]
    q, t = info["quadrics"], info["facets"]
    qm, tm = q["metrics"], t["metrics"]
    scale = info["luma_error_scale"]
    panel_w = 4.6
    fig, axes = plt.subplots(2, 3, figsize=(3 * panel_w, 2 * panel_w * h / w + 2.4), dpi=110,
                             layout="constrained")

    def show(ax, rel, title, **kw):
        img = mpimg.imread(os.path.join(d, rel))
        im = ax.imshow(img, interpolation="nearest", **kw)
        ax.set_title(title, fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
        return im

    tri = "%s triangles, %s" % (thousands(t["triangles"]), t["setting"].replace("eps", "tolerance"))
    show(axes[0][0], info["reference"]["image"], "Reference\n(exact ray casting: the truth)")
    show(axes[0][1], q["image"],
         "Quadrics on the accelerator (hw)\n%s, %s\n%s cycles; silhouette error %.2f px" %
         (q["engine"].split(", ")[-1], q["config"], thousands(q["cycles"]), num(qm["silhouette_hausdorff_px"])))
    show(axes[0][2], t["image"],
         "Triangles: %s\n%s\nsilhouette error %.2f px" % (tri, t["engine"].replace("triangles via ", ""),
                                                         num(tm["silhouette_hausdorff_px"])))
    # Luma errors: 8-bit |dY| levels stored as gray (imread gives 0..1).
    vmax = scale["max"] / 255.0
    kw = dict(cmap="inferno", vmin=0, vmax=vmax)
    im = show(axes[1][0], q["error_image"], "Luma error of the quadrics\nPSNR %s, SSIM %.4f" %
              (db(qm["psnr_db"]), num(qm["ssim"])), **kw)
    show(axes[1][1], t["error_image"], "Luma error of the triangles\nPSNR %s, SSIM %.4f" %
         (db(tm["psnr_db"]), num(tm["ssim"])), **kw)
    cb = fig.colorbar(im, ax=[axes[1][0], axes[1][1]], orientation="horizontal", fraction=0.05, aspect=50)
    ticks = [0, 16, 32, 48, 64]
    cb.set_ticks([v / 255.0 for v in ticks])
    cb.set_ticklabels([str(v) if v < scale["max"] else "%d+" % v for v in ticks])
    cb.set_label("%s against the reference" % scale["unit"], fontsize=8)
    show(axes[1][2], t["coverage_image"],
         "Coverage errors of the triangles\n%s wrong object, %s pinhole, %s spurious px" %
         (thousands(tm["wrong_object_px"]), thousands(tm["pinholes_px"]), thousands(tm["spurious_px"])))
    cols = info["coverage_colours"]
    axes[1][2].legend(handles=[Patch(color=c, label=k) for k, c in cols.items()], loc="upper center",
                      bbox_to_anchor=(0.5, -0.02), ncol=3, fontsize=7, frameon=False)
    fig.suptitle("%s, %dx%d: quadrics on the accelerator against triangles (qacc %s)" %
                 (info["scene"], w, h, info["qacc_version"]), fontsize=11)
    fig.savefig(os.path.join(d, "side_by_side.png"))
    plt.close(fig)


if __name__ == "__main__":
    main()
