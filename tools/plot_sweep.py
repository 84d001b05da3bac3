#!/usr/bin/env python3
"""Plots and report of a `qacc sweep` output directory (docs/SWEEP.md).

    tools/plot_sweep.py DIR

Reads DIR/results.json (written by `qacc sweep` or `qacc sweep --merge`) and writes
  DIR/error_vs_gates.{png,svg}   wrong pixels (%) against the cost model's gate count,
  DIR/error_vs_cycles.{png,svg}  wrong pixels (%) against modeled cycles,
  DIR/psnr_vs_gates.{png,svg}    PSNR against gate count,
one series per scene, Pareto fronts drawn as lines, and DIR/report.html (the spec, the
answer to its target, the fronts, the plots, every row with its thumbnail and error map),
which opens from disk: every link is relative. The C++ writes the data; this script only
draws it (Debian's python3-matplotlib).
"""
import html
import json
import math
import os
import sys

from plot_common import num  # noqa: E402  (also selects matplotlib's Agg backend)
import matplotlib.pyplot as plt  # noqa: E402


def ok_rows(rows):
    return [r for r in rows if r.get("status") == "ok"]


# Wrong percentages of zero are drawn at this floor on the log axis (and said so).
FLOOR = 1e-4


def plot(rows, fronts, cost, cost_label, metric, metric_label, out_base, log_y=True):
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=110)
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    for i, s in enumerate(scenes):
        pts = [(num(r[cost]), num(r[metric])) for r in rows if r["scene"] == s]
        pts = [(x, y) for x, y in pts if not math.isnan(x) and not math.isnan(y)]
        if not pts:
            continue
        ys = [max(y, FLOOR) if log_y else (y if math.isfinite(y) else 99) for _, y in pts]
        color = "C%d" % (i % 10)
        ax.scatter([x for x, _ in pts], ys, s=18, color=color, alpha=0.7, label=s)
        front = fronts.get("scenes", {}).get(s, {}).get(
            "error_vs_gates" if cost == "gates_kge" else "error_vs_cycles", [])
        if metric == "wrong_percent" and front:
            fx = [num(e[cost]) for e in front]
            fy = [max(num(e["wrong_percent"]), FLOOR) for e in front]
            ax.step(fx, fy, where="post", color=color, linewidth=1.2)
    ax.set_xlabel(cost_label)
    ax.set_ylabel(metric_label)
    if log_y:
        ax.set_yscale("log")
        ax.axhline(0.1, color="gray", linestyle=":", linewidth=1)
        ax.text(ax.get_xlim()[0], 0.1, " 0.1 %", va="bottom", color="gray", fontsize=8)
        ax.text(0.99, 0.01, "0 %% wrong drawn at %g %%" % FLOOR, transform=ax.transAxes, ha="right",
                va="bottom", fontsize=7, color="gray")
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8, loc="best")
    ax.set_title(os.path.basename(out_base).replace("_", " "))
    fig.tight_layout()
    fig.savefig(out_base + ".png")
    fig.savefig(out_base + ".svg")
    plt.close(fig)


def fmt(v, digits=4):
    if isinstance(v, float):
        if math.isnan(v):
            return "n/a"
        return ("%%.%dg" % digits) % v
    return html.escape(str(v))


def report(d, res, plots):
    rows = res["rows"]
    fronts = res["fronts"]
    spec = res["spec"]
    out = []
    w = out.append
    w("<!DOCTYPE html><html><head><meta charset='utf-8'><title>qacc sweep %s</title>" %
      html.escape(str(spec.get("name", ""))))
    w("<style>body{font-family:sans-serif;margin:1.5em;max-width:1400px}table{border-collapse:collapse;"
      "font-size:12px}td,th{border:1px solid #ccc;padding:2px 5px;text-align:right}th{background:#eee}"
      "td.l{text-align:left}tr.front{background:#e8f4e8}img.t{image-rendering:pixelated}"
      "pre{background:#f6f6f6;padding:.6em;font-size:12px}</style></head><body>")
    w("<h1>qacc sweep: %s</h1>" % html.escape(str(spec.get("name", ""))))
    if spec.get("description"):
        w("<p>%s</p>" % html.escape(spec["description"]))
    w("<p>%d points x %d scenes = %d rows, engine %s. How to read this report: docs/SWEEP.md.</p>" %
      (res["points"], res["scenes"], len(rows), html.escape(str(spec.get("engine", "hw-cycle")))))
    ans = fronts.get("answer")
    if ans:
        w("<h2>Answer</h2>")
        if ans.get("point") is None:
            w("<p>Target <code>%s</code>: %s.</p>" % (html.escape(ans["target"]), html.escape(ans.get("note", ""))))
        else:
            p = ans.get("worst_psnr_db")
            psnr = ("lowest PSNR %.1f dB" % p if isinstance(p, (int, float))
                    else "every image identical to the reference" if p == "inf" else "PSNR not measured")
            w("<p>Target <code>%s</code> on every scene: the cheapest point is <b>%d (%s)</b>, <b>%.1f kGE</b>, "
              "worst scene %.4f %% wrong, %s, %d cycles over all scenes.</p>" %
              (html.escape(ans["target"]), ans["point"], html.escape(ans["label"]), ans["gates_kge"],
               ans["worst_wrong_percent"], psnr, ans["cycles"]))
    w("<h2>Plots</h2>")
    for p in plots:
        w("<p><a href='%s.svg'><img src='%s.png' alt='%s'></a></p>" % (p, p, p))
    front_items = set()
    for s, f in fronts.get("scenes", {}).items():
        for e in f.get("error_vs_gates", []) + f.get("error_vs_cycles", []):
            front_items.add(e["item"])
    w("<h2>Pareto fronts (all scenes: a point's worst scene)</h2>")
    for name, cost in (("error_vs_gates", "gates_kge"), ("error_vs_cycles", "cycles")):
        w("<h3>%s</h3><table><tr><th>point</th><th>label</th><th>%s</th><th>wrong %%</th></tr>" % (name, cost))
        labels = {r["point"]: r["label"] for r in rows}
        for e in fronts.get("all", {}).get(name, []):
            w("<tr><td>%d</td><td class='l'>%s</td><td>%s</td><td>%s</td></tr>" %
              (e["point"], html.escape(labels.get(e["point"], "")), fmt(num(e[cost]), 7), fmt(num(e["wrong_percent"]))))
        w("</table>")
    w("<h2>Rows</h2><p>Green rows are on a per-scene Pareto front. Thumbnails: the render, its error map "
      "(luma difference as heat; coverage errors painted: wrong object red, pinhole yellow, spurious cyan), "
      "the reference. host_seconds is the host's time for the accelerator render: a row whose "
      "datapath_reused is not empty took the setups, pixel trace and frame of an earlier item of the "
      "same scene and ran only the timed passes, so it is not comparable with the rows that computed "
      "them.</p>")
    cols = ["item", "label", "scene", "status", "gates_kge", "cycles", "fps", "wrong_percent", "wrong_object",
            "pinholes", "spurious", "caps", "psnr_db", "ssim", "silhouette_hausdorff_px", "silhouette_mean_px",
            "depth_max_z24", "depth_mean_z24", "overflows", "host_seconds", "datapath_reused"]
    w("<table><tr>%s<th>render</th><th>error map</th><th>reference</th></tr>" % "".join("<th>%s</th>" % c for c in cols))
    for r in rows:
        cls = " class='front'" if r["item"] in front_items else ""
        cells = []
        for c in cols:
            v = r.get(c, "")
            if c == "status" and v != "ok":
                v = "%s: %s" % (v, r.get("note", ""))
            cells.append("<td%s>%s</td>" % (" class='l'" if c in ("label", "scene", "status") else "",
                                           fmt(num(v)) if isinstance(v, (int, float)) and not isinstance(v, bool)
                                           else html.escape(str(v))))
        imgs = ""
        for k in ("thumbnail", "error_map", "reference_thumbnail"):
            if r.get(k) and os.path.exists(os.path.join(d, r[k])):
                imgs += "<td><a href='%s'><img class='t' src='%s'></a></td>" % (r[k], r[k])
            else:
                imgs += "<td></td>"
        w("<tr%s>%s%s</tr>" % (cls, "".join(cells), imgs))
    w("</table>")
    w("<h2>Spec</h2><pre>%s</pre>" % html.escape(json.dumps(spec, indent=2)))
    w("<p>Data: <a href='results.csv'>results.csv</a>, <a href='results.json'>results.json</a>, "
      "<a href='fronts.csv'>fronts.csv</a>.</p></body></html>")
    with open(os.path.join(d, "report.html"), "w") as f:
        f.write("\n".join(out))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_sweep.py DIR (a qacc sweep output directory)")
    d = sys.argv[1]
    with open(os.path.join(d, "results.json")) as f:
        res = json.load(f)
    rows = ok_rows(res["rows"])
    fronts = res["fronts"]
    plots = []
    if rows:
        plot(rows, fronts, "gates_kge", "gate count (kGE, cost model)", "wrong_percent",
             "wrong pixels (% of pixels either image covers)", os.path.join(d, "error_vs_gates"))
        plots.append("error_vs_gates")
        if any(num(r.get("cycles", 0)) > 0 for r in rows):
            plot(rows, fronts, "cycles", "modeled cycles per frame", "wrong_percent",
                 "wrong pixels (% of pixels either image covers)", os.path.join(d, "error_vs_cycles"))
            plots.append("error_vs_cycles")
        plot(rows, fronts, "gates_kge", "gate count (kGE, cost model)", "psnr_db", "PSNR (dB; inf drawn at 99)",
             os.path.join(d, "psnr_vs_gates"), log_y=False)
        plots.append("psnr_vs_gates")
    report(d, res, plots)
    print("plots and report: %s/report.html" % d)


if __name__ == "__main__":
    main()
