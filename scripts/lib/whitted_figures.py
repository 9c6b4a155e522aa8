#!/usr/bin/env python3
"""Whitted's curved patches against tessellated Gouraud and Phong: docs/results/whitted.md and its
montages, from one `watkins sweep --uv ... --images DIR` run (scripts/lib/whitted_figures.sh).

  whitted_figures.py SWEEP.csv --images DIR --md OUT.md --montage SCENE:N,N,... --out IMAGES
                     [--header LINE] [--uv N,N,...] [--rtl SCENE:MODE:REPORT ...] [--seconds S]

The table has one row per scene, n (u = v polygon cells per patch, or k_u = k_v subpatches per
patch for Whitted's curves) and shading: error of the fixed-point model and of the double
reference against the analytic truth (max, mean |d| in 8-bit levels over pixels showing the same
object), coverage error (pixels covered by only one of image and truth: the silhouette), cycles
per frame (the cycle model), active edges per line (the curved ones), edge-record bits, the
active-edge list's storage (active edges x edge record) and the line buffer's. The findings under
it are computed from the same rows. A montage per scene: rows n, columns truth | Gouraud | Phong
| Whitted, cropped to what the truth covers. --rtl adds a table of `watkins render --rtl` reports
(mismatching pixels, diverging stages, cycles, Newton's iterations).
"""
import argparse
import csv
import os
import re
import sys
import textwrap

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


def span(xs, fmt="{:.2f}", sep=" to "):
    a, b = fmt.format(min(xs)), fmt.format(max(xs))
    return a if a == b else f"{a}{sep}{b}"


def findings(rows):
    """The observations under the table, each figure taken from the rows."""
    ok = [r for r in rows if not r["error"]]
    at = {(stem(r["scene"]), r["shading"], int(r["u"])): r for r in ok if r["u"] == r["v"]}
    scenes = list(dict.fromkeys(stem(r["scene"]) for r in ok))
    ns = sorted({n for _, _, n in at})
    if not scenes or not ns or not all((s, sh, n) in at for s in scenes for sh in ("phong", "whitted") for n in ns):
        return ""
    f = lambda s, sh, n, k: float(at[s, sh, n][k])
    i = lambda s, sh, n, k: int(at[s, sh, n][k])
    lo, hi = ns[0], ns[-1]
    out = []

    cov = "; ".join(f"{s} {i(s, 'whitted', lo, 'truth_coverage_differs')} → {i(s, 'whitted', hi, 'truth_coverage_differs')} "
                    f"against {i(s, 'phong', lo, 'truth_coverage_differs')} → {i(s, 'phong', hi, 'truth_coverage_differs')}"
                    for s in scenes)
    beat = [s for s in scenes
            if i(s, "whitted", lo, "truth_coverage_differs") < i(s, "phong", hi, "truth_coverage_differs")]
    out.append(f"- **Silhouettes.** Coverage error (pixels covered by only one of image and truth) from n = {lo} "
               f"to n = {hi}, curves against polygons: {cov}. The curves' boundaries and silhouettes are the "
               f"surface's own, so what is left is single pixels where a silhouette grazes a pixel centre"
               + (f"; at n = {lo} the curves already have less coverage error than the polygons at n = {hi} on "
                  f"{'every scene' if beat == scenes else ', '.join(beat)}." if beat else "."))

    ratio = {s: [f(s, "whitted", n, "truth_mean") / f(s, "phong", n, "truth_mean") for n in ns
                 if f(s, "phong", n, "truth_mean") > 0] for s in scenes}
    mx = "; ".join(f"{s} {i(s, 'whitted', lo, 'truth_max')} → {i(s, 'whitted', hi, 'truth_max')} against "
                   f"{i(s, 'phong', lo, 'truth_max')} → {i(s, 'phong', hi, 'truth_max')}" for s in scenes)
    out.append("- **Shading.** At the same n the curves' mean error against the truth is "
               + "; ".join(f"{span(ratio[s])} of Phong's on {s}" for s in scenes if ratio[s])
               + f". Their largest error, n = {lo} to {hi}, against the polygons': {mx}. Where a maximum "
               "stays high for every method it is a few pixels every method shares (the teapot's lid rim: "
               "[Whitted's curves](../reference/whitted.md)).")

    extra = {n: [100 * (i(s, "whitted", n, "cycles") / i(s, "phong", n, "cycles") - 1) for s in scenes] for n in ns}
    out.append("- **Cycles.** The curves take more cycles than Phong at the same n, for more edge records (pieces "
               "and silhouettes, one insertion cycle each) and more segments: "
               + "; ".join(f"n = {n}: {span(extra[n], '{:+.1f}')} %" for n in ns) + ". The pixels dominate.")

    bits1 = sorted({int(r["edge_record_bits"]) for r in ok if r["shading"] == "phong"})
    bits3 = sorted({int(r["edge_record_bits"]) for r in ok if r["shading"] == "whitted"})
    lb = sorted({int(r["line_buffer_bits"]) for r in ok})
    hw = (f"- **Hardware.** An order-3 edge record is {span(bits3, '{}', '–')} bits against "
          f"{span(bits1, '{}', '–')} for Phong at order 1 (×{span([b / a for a in bits1 for b in bits3], '{:.2f}', '–')}), "
          "so at the same n the active-edge list stores about twice as much")
    s = "teapot" if "teapot" in scenes else scenes[-1]
    n0 = 4 if 4 in ns else ns[len(ns) // 2]
    w = at[s, "whitted", n0]
    near = min((r for (sc, sh, _), r in at.items() if sc == s and sh == "phong"),
               key=lambda r: abs(int(r["active_list_bits"]) - int(w["active_list_bits"])))
    hw += (f". At about equal list storage, the {s}'s curves at n = {n0} ({int(w['active_list_bits']) / 1000:.1f} kbit, "
           f"mean {float(w['truth_mean']):.2f}, {w['truth_coverage_differs']} coverage pixels) stand against Phong at "
           f"n = {near['u']} ({int(near['active_list_bits']) / 1000:.1f} kbit, mean {float(near['truth_mean']):.2f}, "
           f"{near['truth_coverage_differs']} pixels): the polygons buy the mean, the curves the silhouette. "
           f"The curves need a few more active edges per line than the polygons ({s} n = {n0}: "
           f"{w['active_edges']} against {at[s, 'phong', n0]['active_edges']}). The line buffer does not change "
           f"({span([b / 1000 for b in lb], '{:.1f}', '–')} kbit). The edge incrementer needs three adders per "
           "channel instead of one, no multiplier or divider, one edge per clock either way; its logic is costed "
           "in [Whitted's curves in hardware](../reference/whitted-hardware.md).")
    out.append(hw)
    return "\n".join(out) + "\n"


def rtl_table(specs):
    lines = ["| scene | output | curved edge records, most active | RTL vs model: pixels, diverging stages | "
             "RTL cycles | cycle model | Newton: iterations per crossing; within 1/1024 px after one |",
             "|---|---|---|---|---|---|---|"]
    for spec in specs:
        scene, mode, path = spec.split(":", 2)
        with open(path) as f:
            t = f.read()
        def g(pattern):
            m = re.search(pattern, t, re.M)
            return m.groups() if m else ("—",)

        m = re.search(r"^ +curved edges (\d+) records, at most (\d+) active", t, re.M)
        recs, active = m.groups() if m else ("—", "—")
        it = g(r"^newton +\d+ crossings: ([\d.]+) iterations each")[0]
        close = g(r"\((\d+) of (\d+) stepped crossings within 1/1024 px\)")
        within = f"{100 * int(close[0]) / int(close[1]):.0f} %" if len(close) == 2 and int(close[1]) else "—"
        mism, stages = g(r"^rtl vs model +(\d+) mismatching")[0], g(r"^rtl stages .*, (\d+) diverging")[0]
        cycles, predicted = g(r"^rtl cycles +(\d+)")[0], g(r"^rtl predicted +(\d+)")[0]
        lines.append(f"| {scene} | {mode} | {recs}, {active} | {mism}, {stages} | {cycles} | {predicted} | "
                     f"{it}; {within} |")
    return "\n".join(lines) + "\n"


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reflow import reflow  # noqa: E402  scripts/lib/reflow.py


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


INTRO = """
# Whitted's curved patches

A bicubic patch object (`bezier_patch`, or `patches` of Bézier or uniform B-spline patches) with
`"draw": "curves"` (or `watkins render --patches curves`) is drawn by Whitted's 1978 method instead
of polygons: its boundary curves, its interior curves at `k_u`/`k_v` and its silhouettes
(N·(P − eye) = 0, Whitted's Hermite segment built in (u, v) and mapped onto the surface) are split
where they are not monotonic in screen y, and each is stepped from scan line to scan line by
Newton's iteration with his first-order start and a bisection fallback
([Whitted's curves](../reference/whitted.md), `model/curves`). The hardware steps each curved edge
by forward differences of cubics that preparation fits to the Newton crossings within a stated
bound: configuration `edge_order` 3, three adders per channel, no multiplier, one edge per clock;
the segment former, interpolator, normalizer, Phong shader and depth buffer are unchanged
([Whitted's curves in hardware](../reference/whitted-hardware.md), which also costs the fixed-point
Newton option). Without `--config`, `watkins render` gives a scene with curves the default
configuration at `edge_order` 3.

## Against the analytic truth, with cycles and hardware cost

`watkins sweep scenes/patch.json scenes/bspline.json scenes/teapot.json --shadings
gouraud-eq1,phong,whitted --uv {uv}`. Per patch, Gouraud (eq. 1: Phong's eq. (3) at the vertices)
and Phong draw u = v = n polygon cells; Whitted's curves (`whitted`: the Phong pipeline at
`edge_order` 3) draw the same patch with k_u = k_v = n subpatches, so both have the same cells and
the curves add the exact boundaries and silhouettes. Error in 8-bit levels over the pixels showing
the same object in both images (fixed-point model and double reference); coverage = pixels covered
by only one of image and truth (the silhouette error). Cycles per frame: the cycle model (sparse
output, equal to the RTL's without stalls). Hardware: the edge record of each point's
configuration (default fractions, the integer bits the scene needs, its edge order), the
active-edge list's storage (active edges × record) and the two 320-pixel line buffers. Every column
of every point is in [whitted_compare.csv](whitted_compare.csv).

"""

RTL = """
## On the RTL

The shipped patch scenes carry their interior edges (`k_u`, `k_v`; they do not change the
polygons, which stay the `u` × `v` grid), so `--patches curves` draws them by Whitted's method
through the RTL at one order-3 Phong configuration sized for all three (`watkins size S --shading
phong --patches curves`, the largest of each key: `scenes/sized/patches.curves.phong.json`):
`watkins render scenes/S.json --patches curves --shading phong --rtl --config
scenes/sized/patches.curves.phong.json`. The cycle model's prediction is for no gaps or stalls.
CI co-simulates the same scenes and a synthetic curve scene on that top under random stalls and
gaps.

"""

OUTRO = """
Newton's iteration runs to |E_y(t) − y| < 5e-10 pixel; to 1/1024 pixel one iteration suffices on
most lines, the rest next to y extrema. Not built: clipping curves at the near plane (a patch that
reaches outside the camera's [near, far) is refused, naming the object), and Whitted's
transmission (a one-surface-per-pixel depth buffer cannot blend; see
[Whitted's curves](../reference/whitted.md)).
"""


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv")
    p.add_argument("--images", required=True, help="the sweep's --images folder")
    p.add_argument("--md", required=True, help="the page to write")
    p.add_argument("--montage", action="append", default=[], help="SCENE:N,N,... (a montage per scene)")
    p.add_argument("--out", default="docs/results/images", help="folder of the montages (whitted_SCENE.png)")
    p.add_argument("--header", default="", help="the page's first line")
    p.add_argument("--uv", default="2,4,8,16", help="the sweep's --uv, for the page's command line")
    p.add_argument("--rtl", action="append", default=[], help="SCENE:MODE:REPORT, a `watkins render --rtl` report")
    p.add_argument("--seconds", default="", help="the run's wall time, for the page's last line")
    a = p.parse_args()
    rows = read_rows(a.csv)
    shadings = [s for s in ORDER if any(r["shading"] == s for r in rows) and s != "flat"]
    images = []
    for spec in a.montage:
        scene, ns = spec.split(":")
        out = os.path.join(a.out, f"whitted_{scene}.png")
        montage(a.images, scene, [int(n) for n in ns.split(",")], shadings, out, rows)
        images.append((scene, ns, os.path.basename(out)))
        print(f"wrote {out} ({os.path.getsize(out) // 1024} KB)")
    page = INTRO.replace("{uv}", a.uv) + table(rows) + "\n"
    for scene, ns, name in images:
        page += (f"![analytic truth, Gouraud, Phong and Whitted's curves: {scene}, n = {ns.replace(',', ', ')}]"
                 f"(images/{name})\n\n")
    page += findings(rows)
    if a.rtl:
        page += RTL + rtl_table(a.rtl)
    page += OUTRO
    if a.seconds:
        page += (f"\nThis run took {a.seconds} s of wall time on the machine named above "
                 "(`scripts/lib/whitted_figures.sh`).\n")
    with open(a.md, "w") as f:
        if a.header:
            f.write(a.header.rstrip("\n") + "\n")
        f.write(reflow(page).rstrip("\n") + "\n")
    print(f"wrote {a.md}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
