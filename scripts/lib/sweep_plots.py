#!/usr/bin/env python3
"""Plots of a `watkins sweep`: error against the analytic truth against cycles per frame and
against bits (the active-edge list the scene needs, edge records x edge-record bits), one marker
per shading, Pareto fronts (no other point both cheaper and better) drawn as steps; and the
eq. (1) vs eq. (2) comparison printed as a markdown table (points at the default fractions, 16
bits in every group).

With a fraction-bits axis (several attr_frac values): error against the configuration's
edge-record bits — mean and max, against the truth and against the double reference — one marker
per shading and a Pareto front per shading; and the crossover table: per scene, shading and
tessellation, the attribute fraction width at which the model's mean error against the double
reference (quantization) equals the double reference's mean error against the truth (the
algorithm's own error), interpolated between the bracketing widths on a log scale of the error.
A CSV with that axis gets only these (the others are the default sweep's).

    scripts/lib/sweep_plots.py SWEEP.csv [MORE.csv ...] [--out docs/results/images] [--prefix sweep]
                           [--summary eq1_eq2.md] [--crossover crossover.md]

scripts/lib/sweep.sh runs it and wraps the tables into docs/results/ files.

Several CSVs (shards of one sweep, --shard i/N) are merged by their `point` column.
Installs matplotlib with pip when it is missing.
"""
import argparse
import csv
import math
import os
import subprocess
import sys


def need_matplotlib():
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("sweep_plots: installing matplotlib (pip install --user matplotlib)", file=sys.stderr)
        cmd = [sys.executable, "-m", "pip", "install", "--quiet", "matplotlib"]
        apt = ["apt-get", "install", "-y", "-qq", "python3-matplotlib"]
        if os.geteuid() != 0:
            apt = ["sudo"] + apt
        if subprocess.call(cmd) != 0 and subprocess.call(cmd[:4] + ["--user"] + cmd[4:]) != 0 \
                and subprocess.call(apt) != 0:
            sys.exit("sweep_plots: cannot install matplotlib (pip or apt-get install python3-matplotlib)")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def read_rows(paths):
    rows = {}
    for p in paths:
        with open(p, newline="") as f:
            for r in csv.DictReader(f):
                rows[int(r["point"])] = r
    return [rows[k] for k in sorted(rows)]


def num(r, key):
    v = r.get(key, "")
    return float(v) if v not in ("", None) else None


def pareto(points):
    """Points (cost, error) not dominated: sorted by cost, each strictly better than all cheaper."""
    front, best = [], math.inf
    for c, e in sorted(points):
        if e < best:
            front.append((c, e))
            best = e
    return front


SHADING_STYLE = {"flat": ("tab:gray", "s"), "gouraud-eq1": ("tab:blue", "o"),
                 "gouraud-eq2": ("tab:cyan", "x"), "phong": ("tab:red", "^")}


def plot(plt, rows, cost_key, cost_label, err_key, err_label, path, title):
    scenes = sorted({r["scene"] for r in rows})
    fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 4.2), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        mine = [r for r in rows if r["scene"] == scene and num(r, cost_key) is not None
                and num(r, err_key) is not None]
        for shading, (color, marker) in SHADING_STYLE.items():
            pts = [(num(r, cost_key), num(r, err_key), r) for r in mine if r["shading"] == shading]
            if not pts:
                continue
            ax.scatter([p[0] for p in pts], [p[1] for p in pts], c=color, marker=marker, label=shading, zorder=3)
            for c, e, r in pts:
                ax.annotate(f'{r["u"]}×{r["v"]}', (c, e), fontsize=6, xytext=(3, 3), textcoords="offset points")
        front = pareto([(num(r, cost_key), num(r, err_key)) for r in mine])
        if front:
            xs, ys = zip(*front)
            ax.step(xs, ys, where="post", color="black", lw=1, ls="--", label="Pareto front", zorder=2)
            ax.scatter(xs, ys, facecolors="none", edgecolors="black", s=120, zorder=4)
        costs = [num(r, cost_key) for r in mine]
        if costs and max(costs) > 20 * min(costs):  # bits span decades; cycles a few percent
            ax.set_xscale("log")
        else:
            ax.ticklabel_format(axis="x", style="plain", useOffset=False)
        ax.set_xlabel(cost_label)
        ax.set_ylabel(err_label)
        ax.set_title(f"{os.path.splitext(os.path.basename(scene))[0]}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"sweep_plots: wrote {path}")


def at_default_fractions(r):
    return all(r.get(k) in (None, "", "16") for k in ("attr_frac", "x_frac", "depth_frac"))


def scene_name(scene):
    return os.path.splitext(os.path.basename(scene))[0]


def plot_frac(plt, rows, err_key, err_label, path, title):
    """Error against edge-record bits over the fraction-bits axis; a Pareto front per shading."""
    scenes = sorted({r["scene"] for r in rows})
    fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 4.4), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        mine = [r for r in rows if r["scene"] == scene and num(r, "edge_record_bits") is not None
                and num(r, err_key) is not None]
        for shading, (color, marker) in SHADING_STYLE.items():
            pts = [(num(r, "edge_record_bits"), num(r, err_key), r) for r in mine if r["shading"] == shading]
            if not pts:
                continue
            ax.scatter([p[0] for p in pts], [p[1] for p in pts], c=color, marker=marker, s=18, label=shading,
                       zorder=3, alpha=0.7)
            front = pareto([(c, e) for c, e, _ in pts])
            xs, ys = zip(*front)
            ax.step(xs, ys, where="post", color=color, lw=1, ls="--", zorder=2)
            ax.scatter(xs, ys, facecolors="none", edgecolors=color, s=70, zorder=4)
            for c, e, r in pts:  # the attribute fraction of each front point
                if (c, e) in front:
                    ax.annotate(r["attr_frac"], (c, e), fontsize=6, xytext=(3, 3), textcoords="offset points")
        ax.set_yscale("symlog", linthresh=0.01)
        ax.set_xlabel("edge-record bits of the configuration")
        ax.set_ylabel(err_label)
        ax.set_title(scene_name(scene))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, title="dashed: Pareto front; labels: attr frac bits", title_fontsize=6)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"sweep_plots: wrote {path}")


def crossover(points, algorithm):
    """points: (width, quantization error) sorted by width. The width where the quantization error
    falls to `algorithm`: (text, value or None)."""
    above = [w for w, e in points if e > algorithm]
    if not above:
        return f"≤ {points[0][0]} (below at every width)", None
    w_lo = max(above)
    higher = [(w, e) for w, e in points if w > w_lo]
    if not higher:
        return f"> {w_lo} (above at every width)", None
    w_hi, e_hi = higher[0]
    e_lo = dict(points)[w_lo]
    if e_hi <= 0:  # no log: linear
        t = (e_lo - algorithm) / (e_lo - e_hi)
    else:
        t = (math.log(e_lo) - math.log(algorithm)) / (math.log(e_lo) - math.log(e_hi))
    w = w_lo + t * (w_hi - w_lo)
    return f"{w:.1f} (between {w_lo} and {w_hi})", w


def crossover_table(rows):
    groups = {}
    for r in rows:
        if num(r, "double_mean") is None or num(r, "double_truth_mean") is None:
            continue
        key = (scene_name(r["scene"]), r["shading"], int(r["u"]), int(r["v"]), r.get("x_frac"), r.get("depth_frac"))
        groups.setdefault(key, []).append(r)
    order = list(SHADING_STYLE)
    out = ["| scene | shading | u×v | attr group | x / depth frac | algorithm: double vs truth mean | "
           "model vs double mean at the widths swept (attr frac: error) | width where quantization = algorithm |",
           "|---|---|---|---|---|---|---|---|"]
    for key in sorted(groups, key=lambda k: (k[0], order.index(k[1]) if k[1] in order else 9, k[2], k[3], k[4], k[5])):
        rs = sorted(groups[key], key=lambda r: int(r["attr_frac"]))
        algorithm = num(rs[0], "double_truth_mean")
        points = [(int(r["attr_frac"]), num(r, "double_mean")) for r in rs]
        text, _ = crossover(points, algorithm)
        swept = ", ".join(f"{w}: {e:g}" for w, e in points)
        scene, shading, u, v, xf, df = key
        out.append(f"| {scene} | {shading} | {u}×{v} | {rs[0].get('attr_group', '')} | {xf} / {df} | "
                   f"{algorithm:.4f} | {swept} | {text} |")
    return "\n".join(out) + "\n"


def eq1_eq2_summary(rows):
    """Per scene and tessellation: Gouraud eq. (1) against eq. (2), both against the truth."""
    by = {}
    for r in rows:
        by[(r["scene"], r["u"], r["v"], r["shading"])] = r
    out = ["| scene | u×v | eq. 1 vs truth max / mean / RMSE / Mach | eq. 2 vs truth max / mean / RMSE / Mach | "
           "pixels compared eq. 1 / eq. 2 |", "|---|---|---|---|---|"]
    for (scene, u, v, shading), r1 in sorted(by.items(), key=lambda kv: (kv[0][0], int(kv[0][1]))):
        if shading != "gouraud-eq1" or (scene, u, v, "gouraud-eq2") not in by:
            continue
        r2 = by[(scene, u, v, "gouraud-eq2")]

        def cell(r):
            return f'{r["truth_max"]} / {r["truth_mean"]} / {r["truth_rmse"]} / {r["truth_mach"]}'
        name = os.path.splitext(os.path.basename(scene))[0]
        out.append(f'| {name} | {u}×{v} | {cell(r1)} | {cell(r2)} | {r1["truth_compared"]} / {r2["truth_compared"]} |')
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--out", default="docs/results/images", help="folder of the PNGs")
    ap.add_argument("--prefix", default="sweep", help="PNG name prefix")
    ap.add_argument("--summary", help="markdown file for the eq. (1) vs eq. (2) table")
    ap.add_argument("--crossover", help="markdown file for the fraction-width crossover table")
    a = ap.parse_args()
    all_rows = [r for r in read_rows(a.csv) if not r.get("error")]
    rows = [r for r in all_rows if at_default_fractions(r)]
    plt = need_matplotlib()
    os.makedirs(a.out, exist_ok=True)
    if len({r.get("attr_frac") for r in all_rows}) > 1:
        for err, label in (("truth_mean", "mean |Δ| vs analytic truth"), ("truth_max", "max |Δ| vs analytic truth"),
                           ("double_mean", "mean |Δ| vs double reference"),
                           ("double_max", "max |Δ| vs double reference")):
            plot_frac(plt, all_rows, err, label + " (8-bit levels)",
                      os.path.join(a.out, f"{a.prefix}_{err}_erbits.png"),
                      "error against edge-record bits (fraction bits of the shade / normal swept)")
        table = crossover_table(all_rows)
        print(table)
        if a.crossover:
            with open(a.crossover, "w") as f:
                f.write(table)
        return  # a fraction-bits sweep: the plots at the default fractions are the default sweep's
    have_cycles = any(num(r, "cycles") is not None for r in rows)
    for err, label in (("truth_mean", "mean |Δ| vs analytic truth (8-bit levels)"),
                       ("truth_max", "max |Δ| vs analytic truth (8-bit levels)")):
        tag = err.split("_")[1]
        if have_cycles:
            plot(plt, rows, "cycles", "cycles per frame", err, label,
                 os.path.join(a.out, f"{a.prefix}_{tag}_cycles.png"), "error against cycles")
        plot(plt, rows, "active_list_bits", "active-edge list bits the scene needs (active edges × edge-record bits)",
             err, label, os.path.join(a.out, f"{a.prefix}_{tag}_bits.png"), "error against bits")
    summary = eq1_eq2_summary(rows)
    print(summary)
    if a.summary:
        with open(a.summary, "w") as f:
            f.write(summary)


if __name__ == "__main__":
    main()
