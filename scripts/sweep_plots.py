#!/usr/bin/env python3
"""Plots of a `watkins sweep`: error against the analytic truth against cycles per frame and
against bits (the active-edge list the scene needs, edge records x edge-record bits), one marker
per shading, Pareto fronts (no other point both cheaper and better) drawn as steps; and the
eq. (1) vs eq. (2) comparison printed as a markdown table.

    scripts/sweep_plots.py SWEEP.csv [MORE.csv ...] [--out docs] [--summary docs/sweep_eq1_eq2.md]

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
    ap.add_argument("--out", default="docs", help="folder of the PNGs")
    ap.add_argument("--prefix", default="sweep", help="PNG name prefix")
    ap.add_argument("--summary", help="markdown file for the eq. (1) vs eq. (2) table")
    a = ap.parse_args()
    rows = [r for r in read_rows(a.csv) if not r.get("error")]
    plt = need_matplotlib()
    os.makedirs(a.out, exist_ok=True)
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
