#!/usr/bin/env python3
"""Whitted's curved patches against tessellated Gouraud and Phong: the comparison table and the
side-by-side images of scripts/lib/whitted_figures.sh, from one `watkins sweep --uv ... --images DIR` run.

  whitted_figures.py SWEEP.csv --images DIR --md OUT.md --montage SCENE:N,N,... --out DOCS

The table has one row per scene, n (u = v polygon cells per patch, or k_u = k_v subpatches per
patch for Whitted's curves) and shading: error of the fixed-point model and of the double
reference against the analytic truth (max, mean |d| in 8-bit levels over pixels showing the same
object), coverage error (pixels covered by only one of image and truth: the silhouette), cycles
per frame (the cycle model), active edges per line (the curved ones), edge-record bits, the
active-edge list's storage (active edges x edge record) and the line buffer's. A montage per
scene: rows n, columns truth | Gouraud | Phong | Whitted, cropped to what the truth covers.
"""
import argparse
import csv
import os
import sys

NAMES = {"gouraud-eq1": "Gouraud (eq. 1)", "gouraud-eq2": "Gouraud (eq. 2)", "phong": "Phong",
         "whitted": "Whitted curves", "flat": "flat"}
ORDER = ["flat", "gouraud-eq1", "gouraud-eq2", "phong", "whitted"]


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def stem(scene):
    return os.path.splitext(os.path.basename(scene))[0]


def table(rows):
    head = ("| scene | n | shading | fixed vs truth max / mean | double vs truth max / mean | "
            "coverage px fixed / double | cycles per frame | active edges (curved) | edge records | "
            "edge record bits (order) | active list kbit | line buffer kbit |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    lines = []
    scenes = list(dict.fromkeys(r["scene"] for r in rows))  # in the sweep's order
    key = lambda r: (scenes.index(r["scene"]), int(r["u"]), ORDER.index(r["shading"]) if r["shading"] in ORDER else 99)
    for r in sorted(rows, key=key):
        n = r["u"] if r["u"] == r["v"] else f'{r["u"]}×{r["v"]}'
        if r["error"]:
            lines.append(f'| {stem(r["scene"])} | {n} | {NAMES.get(r["shading"], r["shading"])} | '
                         f'{r["error"]} |||||||||\n')
            continue
        curved = f' ({r["curve_active_edges"]})' if r["curve_active_edges"] not in ("", "0") else ""
        lines.append(
            f'| {stem(r["scene"])} | {n} | {NAMES.get(r["shading"], r["shading"])} | '
            f'{r["truth_max"]} / {float(r["truth_mean"]):.2f} | '
            f'{r["double_truth_max"]} / {float(r["double_truth_mean"]):.2f} | '
            f'{r["truth_coverage_differs"]} / {r["double_truth_coverage_differs"]} | {r["cycles"]} | '
            f'{r["active_edges"]}{curved} | {r["edge_records"]} | {r["edge_record_bits"]} ({r["edge_order"]}) | '
            f'{int(r["active_list_bits"]) / 1000:.1f} | {int(r["line_buffer_bits"]) / 1000:.1f} |\n')
    return head + "".join(lines)


def montage(images, scene, ns, shadings, out, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    truth = plt.imread(os.path.join(images, f"{scene}_truth.png"))[:, :, :3]
    # Crop to what the truth shows (it differs from the background), with a margin.
    diff = np.abs(truth - truth[0, 0]).sum(axis=2) > 1e-6
    ys, xs = np.nonzero(diff)
    m = 6
    y0, y1 = max(0, ys.min() - m), min(truth.shape[0], ys.max() + m + 1)
    x0, x1 = max(0, xs.min() - m), min(truth.shape[1], xs.max() + m + 1)
    crop = lambda a: a[y0:y1, x0:x1]
    uv = {(stem(r["scene"]), r["shading"], int(r["u"])): r for r in rows}
    cols = ["truth"] + shadings
    h, w = y1 - y0, x1 - x0
    dpi, label, title, gap = 100, 16, 26, 4  # pixel layout: the images at 1:1, titles above them
    W, H = label + len(cols) * (w + gap), len(ns) * (title + h + gap)
    fig = plt.figure(figsize=(W / dpi, H / dpi), dpi=dpi)
    for i, n in enumerate(ns):
        fig.text(label / 2 / W, 1 - (i * (title + h + gap) + title + h / 2) / H, f"n = {n}", rotation=90,
                 ha="center", va="center", fontsize=8)
        for j, c in enumerate(cols):
            ax = fig.add_axes([(label + j * (w + gap)) / W, 1 - (i * (title + h + gap) + title + h) / H, w / W, h / H])
            ax.set_axis_off()
            if c == "truth":
                ax.imshow(crop(truth), interpolation="nearest")
                ax.set_title("analytic truth", fontsize=7)
                continue
            r = uv.get((scene, c, n))
            path = os.path.join(images, f"{scene}_{c}_{n}x{n}.png")
            if r is None or not os.path.exists(path):
                continue
            ax.imshow(crop(plt.imread(path)[:, :, :3]), interpolation="nearest")
            ax.set_title(f'{NAMES.get(c, c)}\nmean {float(r["truth_mean"]):.2f}, '
                         f'{r["truth_coverage_differs"]} px cov.', fontsize=7, linespacing=1.1)
    fig.savefig(out, dpi=dpi)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv")
    p.add_argument("--images", required=True, help="the sweep's --images folder")
    p.add_argument("--md", required=True, help="the comparison table to write")
    p.add_argument("--montage", action="append", default=[], help="SCENE:N,N,... (a montage per scene)")
    p.add_argument("--out", default="docs", help="folder of the montages (whitted_SCENE.png)")
    p.add_argument("--header", default="", help="text put above the table")
    a = p.parse_args()
    rows = read_rows(a.csv)
    with open(a.md, "w") as f:
        if a.header:
            f.write(a.header.rstrip("\n") + "\n\n")
        f.write(table(rows))
    shadings = [s for s in ORDER if any(r["shading"] == s for r in rows) and s != "flat"]
    for spec in a.montage:
        scene, ns = spec.split(":")
        out = os.path.join(a.out, f"whitted_{scene}.png")
        montage(a.images, scene, [int(n) for n in ns.split(",")], shadings, out, rows)
        print(f"wrote {out} ({os.path.getsize(out) // 1024} KB)")
    print(f"wrote {a.md}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
