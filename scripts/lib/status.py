#!/usr/bin/env python3
"""The README's status table: one row per target of the product, with the figure the generated
result files in docs/results/ hold now, whether it is met, and what limits it. Every figure is read
from those files (synth/<part>.csv, bench.csv, verify.md, sweep.csv), so README carries no typed
figures: `scripts/results status` writes the table between README's status markers, and the ctest
docs_status_current fails when README's table differs from what this prints.

    scripts/lib/status.py                 print the block (markers included)
    scripts/lib/status.py --write FILE    replace FILE's block between the markers
    scripts/lib/status.py --check FILE    exit 1 when FILE's block differs from the printed one

WATKINS_RESULTS_DIR replaces docs/results (links stay docs/results/...: they are README's).
"""
import argparse
import csv
import os
import re
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RESULTS = os.environ.get("WATKINS_RESULTS_DIR", os.path.join(ROOT, "docs", "results"))
BEGIN, END = "<!-- status:begin -->", "<!-- status:end -->"
LINK = "docs/results/"  # README's links to the result files


def path(name):
    return os.path.join(RESULTS, name)


def link(name, text=None):
    return "[%s](%s%s)" % (text or name, LINK, name)


def read_csv(name):
    if not os.path.exists(path(name)):
        return None
    with open(path(name), newline="") as f:
        return list(csv.DictReader(f))


def md_tables(name):
    """Every markdown table of a file: a list of lists of rows (dicts keyed by the header cells)."""
    if not os.path.exists(path(name)):
        return None
    tables, header, rows = [], None, None
    for line in open(path(name)):
        line = line.strip()
        if not line.startswith("|"):
            header = rows = None
            continue
        cells = [c.strip() for c in line.strip("|").split("|")]
        if header is None:
            header, rows = cells, []
            tables.append(rows)
        elif set("".join(cells)) <= set("-: "):
            continue
        else:
            rows.append(dict(zip(header, cells)))
    return tables


def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return None


def thousands(v):
    return "{:,}".format(int(v))


def mhz(v):
    return "%.1f" % v


def missing(what, cmd):
    return ["not measured", "—", "no %s yet (`scripts/results %s`)" % (what, cmd)]


# ---- RTL against the model (verify.md) ------------------------------------------------------
def rtl_rows():
    tables = md_tables("verify.md")
    target = "RTL ≡ model: 0 mismatching pixels and cycles equal to the cycle model's, every shipped scene, both shadings"
    if not tables or not tables[0]:
        return [[target] + missing("verify.md", "verify")]
    runs = [r for t in tables for r in t if "mismatching pixels" in r]
    ran = [r for r in runs if num(r["mismatching pixels"]) is not None]
    clean = [r for r in ran if num(r["mismatching pixels"]) == 0 and num(r.get("diverging stages", "0")) == 0]
    equal = [r for r in ran if r.get("cycles = predicted") == "yes"]
    refused = [r for r in runs if r not in ran]
    bad = [r for r in ran if r not in clean or r not in equal]
    scenes = len({r["scene"] for r in runs})
    figure = ("0 mismatching pixels in %d of %d frames, cycles equal in %d of %d (%d scenes, default and sized "
              "configurations, full-frame and sparse; %s)" % (len(clean), len(ran), len(equal), len(ran), scenes,
                                                                link("verify.md")))
    if refused:
        figure += "; %d not run" % len(refused)
    met = "yes" if ran and not bad and not refused else "no"
    limits = "—"
    if bad or refused:
        names = ["%s %s %s %s" % (r["scene"], r["shading"], r.get("configuration", ""), r.get("output", ""))
                 for r in (bad + refused)[:3]]
        limits = "; ".join(n.strip() for n in names) + (" and more" if len(bad) + len(refused) > 3 else "")
    return [[target, figure, met, limits]]


# ---- Error against the truth and against the double reference (sweep.csv) -------------------
def sweep_rows():
    rows = read_csv("sweep.csv")
    t_truth = "Error against the analytic truth: Phong at most Gouraud's (sphere, max and mean)"
    t_quant = "Fixed point against double: below the algorithm's own error (mean; sphere, cone, default scene as shipped)"
    if not rows:
        return [[t_truth] + missing("sweep.csv", "sweep"), [t_quant] + missing("sweep.csv", "sweep")]
    rows = [r for r in rows if not r.get("error") and all(r.get(k) in ("", None, "16")
                                                          for k in ("attr_frac", "x_frac", "depth_frac"))]
    sphere = {r["shading"]: r for r in rows if os.path.basename(r["scene"]) == "sphere.json" and num(r["tess"]) == 1}
    out = []
    g, p = sphere.get("gouraud-eq1"), sphere.get("phong")
    if g and p:
        def pair(r, a, b):
            return "%s / %s" % (r[a], "%.2f" % num(r[b]))
        met = num(p["truth_max"]) <= num(g["truth_max"]) and num(p["truth_mean"]) <= num(g["truth_mean"])
        out.append([t_truth,
                    "Gouraud %s, Phong %s levels (max / mean; sphere %s×%s; %s)"
                    % (pair(g, "truth_max", "truth_mean"), pair(p, "truth_max", "truth_mean"), g["u"], g["v"],
                       link("sweep.md")),
                    "yes" if met else "no",
                    "the tessellation: the double reference errs as much (Gouraud %s, Phong %s)"
                    % (pair(g, "double_truth_max", "double_truth_mean"), pair(p, "double_truth_max", "double_truth_mean"))])
    else:
        out.append([t_truth] + missing("sphere rows in sweep.csv", "sweep"))
    # The scenes as shipped (tessellation 1): there the quantization has to cost less than the
    # algorithm; finer tessellations shrink the algorithm's error until the fraction bits show.
    pts = [r for r in rows if num(r["double_mean"]) is not None and num(r["double_truth_mean"]) is not None]
    shipped = [r for r in pts if num(r["tess"]) == 1]
    below = [r for r in shipped if num(r["double_mean"]) < num(r["double_truth_mean"])]
    if shipped:
        def ratio(r):
            return num(r["double_mean"]) / max(num(r["double_truth_mean"]), 1e-9)

        def name(r):
            return "%s %s %s×%s" % (os.path.splitext(os.path.basename(r["scene"]))[0], r["shading"], r["u"], r["v"])
        worst = max(shipped, key=ratio)
        figure = "%d of %d shipped tessellations" % (len(below), len(shipped))
        if g and p:
            figure += "; sphere: Gouraud %.3f against %.2f, Phong %.3f against %.2f levels" % (
                num(g["double_mean"]), num(g["double_truth_mean"]), num(p["double_mean"]), num(p["double_truth_mean"]))
        figure += " (%s)" % link("sweep.md")
        limits = "closest: %s, %.3f against %.2f" % (name(worst), num(worst["double_mean"]), num(worst["double_truth_mean"]))
        finer = [r for r in pts if r not in shipped and num(r["double_mean"]) >= num(r["double_truth_mean"])]
        if finer:
            f = max(finer, key=ratio)
            limits += "; finer tessellation brings the algorithm's error below it (%s: %.3f against %.2f)" % (
                name(f), num(f["double_mean"]), num(f["double_truth_mean"]))
        out.append([t_quant, figure, "yes" if len(below) == len(shipped) else "no",
                    limits + "; fraction bits against error: " + link("sweep_frac.md")])
    else:
        out.append([t_quant] + missing("points in sweep.csv", "sweep"))
    return out


# ---- Speed (bench.csv) ----------------------------------------------------------------------
def bench_rows():
    rows = read_csv("bench.csv")
    t_mesa = "Model speed: ≥ 1.5× Mesa llvmpipe (one thread), Gouraud, default scene"
    t_rtl = "Verilated Gouraud top: ≥ 2.5 M cycles/s (plain C++ harness, stage checker on)"
    if not rows:
        return [[t_mesa] + missing("bench.csv", "bench"), [t_rtl] + missing("bench.csv", "bench")]
    v = {r["key"]: num(r["value"]) for r in rows}
    out = []
    model, mesa = v.get("model.gouraud.default"), v.get("mesa.gouraud.default")
    if model and mesa:
        ratio = model / mesa
        ipf = v.get("instructions_per_fragment.default")
        out.append([t_mesa, "%.2f× (%.1f against %.1f M fragments/s; %s)" % (ratio, model, mesa, link("bench.md")),
                    "yes" if ratio >= 1.5 else "no",
                    "%s instructions per fragment (callgrind)" % thousands(ipf) if ipf else "—"])
    else:
        out.append([t_mesa] + missing("model and Mesa rows in bench.csv", "bench"))
    cps = v.get("verilator.cc.gouraud")
    if cps:
        ipc = v.get("verilator_ipc.cc.gouraud.checker")
        out.append([t_rtl, "%.2f M cycles/s (%s)" % (cps / 1e6, link("bench.md")), "yes" if cps >= 2.5e6 else "no",
                    "%s instructions per simulated cycle (callgrind)" % thousands(ipc) if ipc else "—"])
    else:
        out.append([t_rtl] + missing("Verilator rows in bench.csv", "bench"))
    return out


# ---- Synthesis (synth/<part>.csv) -----------------------------------------------------------
def runs(rows, design, target):
    return [r for r in rows if r["design"] == design and r["target"] == target]


def fmax_row(part, design, label, goal):
    title = "%s top on the ECP5-85: ≥ %d MHz" % (label, goal)
    rows = read_csv("synth/%s.csv" % part)
    mine = runs(rows or [], design, "ecp5-85")
    routed = [r for r in mine if (num(r["fmax_mhz"]) or 0) > 0]
    if not mine:
        return [title] + missing("%s run on the ECP5-85" % design, "synth")
    if not routed:
        return [title, "no Fmax: %s (%s)" % (", ".join(sorted({r["result"] for r in mine})), link("synth.md")), "no",
                "the run did not finish routing; `watkins synth --timeout` sets its limit"]
    fs = [num(r["fmax_mhz"]) for r in routed]
    seeds = [r.get("seed", "default") or "default" for r in routed]
    if len(routed) == 1:
        figure = "%s MHz" % mhz(fs[0])
    else:
        figure = "%s MHz (seeds %s; median %s)" % (" / ".join(mhz(f) for f in fs), " / ".join(seeds),
                                                    mhz(statistics.median(fs)))
    figure += " (%s)" % link("synth.md")
    slow = min(routed, key=lambda r: num(r["fmax_mhz"]))
    limits = "critical path `%s` → `%s`, %.1f ns" % (slow["path_start"], slow["path_end"], num(slow["path_ns"]))
    return [title, figure, "yes" if min(fs) >= goal else "no", limits]


def fit_row():
    title = ("Gouraud top on the iCE40 UP5K (compact micro-architecture): fits (≤ 5,280 logic cells, ≤ 8 DSP, "
             "≤ 30 EBR), routed at ≥ 25.2 MHz")
    rows = read_csv("synth/compact.csv")
    mine = runs(rows or [], "top-compact", "ice40-up5k")
    if not mine:
        return [title] + missing("top-compact run on the UP5K", "synth")
    r = mine[0]
    try:
        cells = int(r["logic_cells"].split("/")[0].strip())
    except ValueError:
        return [title, "no place and route: %s (%s)" % (r["result"], link("synth.md")), "no", r["result"]]
    dsp, bram = int(r["dsp"]), int(r["bram"])
    fmax = num(r["fmax_mhz"]) or 0
    met = cells <= 5280 and dsp <= 8 and bram <= 30 and fmax >= 25.2
    figure = "%s logic cells, %d DSP, %d EBR, %s MHz (%s; the pipelined top: %s)" % (
        thousands(cells), dsp, bram, mhz(fmax), link("compact.md"), pipelined_up5k())
    if fmax < 25.2 and r.get("path_start"):
        limits = "critical path `%s` → `%s`, %.1f ns" % (r["path_start"], r["path_end"], num(r["path_ns"]))
    else:
        limits = "—" if met else "area"
    return [title, figure, "yes" if met else "no", limits]


def compact_phong_row():
    title = ("Phong top on the iCE40 UP5K (compact, narrow Phong formats): fits (≤ 5,280 logic cells, ≤ 8 DSP, "
             "≤ 30 EBR), routed at ≥ 25.2 MHz")
    mine = runs(read_csv("synth/compact_phong.csv") or [], "top-compact-phong", "ice40-up5k")
    if not mine:
        return [title] + missing("top-compact-phong run on the UP5K", "compact-phong")
    r = mine[0]
    cells = int(r["logic_cells"].split("/")[0].strip())
    dsp, bram = int(r["dsp"]), int(r["bram"])
    fmax = num(r["fmax_mhz"]) or 0
    met = cells <= 5280 and dsp <= 8 and bram <= 30 and fmax >= 25.2
    figure = "%s logic cells, %d DSP, %d EBR, %s (%s)" % (
        thousands(cells), dsp, bram, "%s MHz" % mhz(fmax) if fmax else r["result"], link("compact_phong.md"))
    over = []
    if cells > 5280:
        over.append("%s logic cells" % thousands(cells - 5280))
    if dsp > 8:
        over.append("%d DSP" % (dsp - 8))
    if bram > 30:
        over.append("%d EBR" % (bram - 30))
    limits = "—" if met else ("area: %s over the part" % ", ".join(over) if over else "the clock")
    return [title, figure, "yes" if met else "no", limits]


def pipelined_up5k():
    mine = runs(read_csv("synth/gouraud.csv") or [], "top-gouraud", "ice40-up5k")
    if not mine:
        return "not run"
    r = mine[0]
    return "%s logic cells, %s DSP, %s EBR" % (thousands(int(r["logic_cells"].split("/")[0])), r["dsp"], r["bram"])


# ---- The board (board.md) --------------------------------------------------------------------
def board_row():
    title = ("ULX3S board top, default scene: a bitstream with every clock's constraint met, "
             "0 missed lines racing the beam")
    if not os.path.exists(path("board.md")):
        return [title] + missing("board.md", "board")
    text = open(path("board.md")).read()
    section = text.split("\n## ")[1] if "\n## " in text else ""
    m = re.search(r"^missed\s+(\d+) lines", section, re.M)
    slack = re.search(r"^worst line\s+.*?slack (-?\d+) pipeline clocks", section, re.M)
    clocks = []
    for t in md_tables("board.md") or []:
        if t and "routed Fmax MHz" in t[0]:
            clocks = t
            break
    if m is None or not clocks:
        return [title, "no bitstream (%s)" % link("board.md"), "no", "the board build failed; see %s" % link("board.md")]
    missed = int(m.group(1))
    met = missed == 0 and all(c["met"] == "yes" for c in clocks)
    figure = "; ".join("%s %s MHz (≥ %s)" % (c["clock"].strip("`"), c["routed Fmax MHz"], c["constraint MHz"])
                       for c in clocks if c["clock"].strip("`") in ("clk_pipe", "clk_pixel", "clk_tmds"))
    figure += "; %d missed lines, worst slack %s pipeline clocks (%s)" % (missed, slack.group(1) if slack else "?",
                                                                        link("board.md"))
    tightest = min(clocks, key=lambda c: (num(c["routed Fmax MHz"]) or 0) / (num(c["constraint MHz"]) or 1))
    limits = "the tightest clock: %s, %s of its constraint" % (tightest["clock"], tightest["margin"])
    return [title, figure, "yes" if met else "no", limits]


def icebreaker_row():
    title = ("iCEBreaker board top, default scene: a bitstream at ≥ 25.125 MHz (nextpnr's default seed), "
             "0 missed lines racing the beam")
    if not os.path.exists(path("icebreaker.md")):
        return [title] + missing("icebreaker.md", "icebreaker")
    text = open(path("icebreaker.md")).read()
    head = text.split("\n### ")[0]
    m = re.search(r"^missed\s+(\d+) lines", head, re.M)
    slack = re.search(r"^worst line\s+.*?slack (-?\d+) pipeline clocks", head, re.M)
    seeds = []  # (seed label, clock row, resources) per build, in the file's order
    for section in text.split("\n### ")[1:]:
        sm = re.match(r"`watkins board build --board icebreaker --seed (\d+)`", section)
        clock = re.search(r"^\| `clk` \| ([\d.]+) \| ([\d.]+) \| ([^|]+) \| ([^|]+) \|", section, re.M)
        if not sm or not clock:
            continue
        res = dict(re.findall(r"^\| (ICESTORM_LC|ICESTORM_RAM|ICESTORM_SPRAM|ICESTORM_DSP) \| (\d+) \|", section, re.M))
        seeds.append((int(sm.group(1)), clock, res))
    if m is None or not seeds or seeds[0][0] != 0:
        return [title, "no bitstream (%s)" % link("icebreaker.md"), "no",
                "the board build failed; see %s" % link("icebreaker.md")]
    missed = int(m.group(1))
    _, clock, res = seeds[0]
    achieved, constraint, margin = float(clock.group(2)), float(clock.group(1)), clock.group(3).strip()
    met = missed == 0 and achieved >= constraint
    figure = "clk %s MHz (≥ %s)" % (clock.group(2), clock.group(1))
    if len(seeds) > 1:
        figure += "; seeds %s: %s" % (", ".join(str(s) for s, _, _ in seeds[1:]),
                                      ", ".join(c.group(2) for _, c, _ in seeds[1:]))
    if res:
        figure += "; %s / 5,280 logic cells, %s / 30 EBR, %s / 4 SPRAM" % (
            thousands(res.get("ICESTORM_LC", 0)), res.get("ICESTORM_RAM", 0), res.get("ICESTORM_SPRAM", 0))
    figure += "; %d missed lines, worst slack %s clocks (%s)" % (missed, slack.group(1) if slack else "?",
                                                               link("icebreaker.md"))
    limits = "the clock's margin at the default seed: %s" % margin
    return [title, figure, "yes" if met else "no", limits]


def table():
    rows = rtl_rows() + sweep_rows() + bench_rows() + [
        fmax_row("phong", "top-phong", "Phong", 100), fmax_row("gouraud", "top-gouraud", "Gouraud", 125), fit_row(),
        compact_phong_row(), board_row(), icebreaker_row()]
    out = [BEGIN,
           "<!-- generated by `scripts/results status` from docs/results/; the ctest docs_status_current checks it -->",
           "",
           "| target | measured | met | what limits it |",
           "|---|---|---|---|"]
    out += ["| %s |" % " | ".join(c.replace("|", "\\|") for c in r) for r in rows]
    out.append(END)
    return "\n".join(out)


def split(text, name):
    b, e = text.find(BEGIN), text.find(END)
    if b < 0 or e < b:
        sys.exit("status: %s has no %s ... %s block (put the two lines where the table goes)" % (name, BEGIN, END))
    return text[:b], text[b:e + len(END)], text[e + len(END):]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    g = ap.add_mutually_exclusive_group()
    g.add_argument("--write", metavar="FILE")
    g.add_argument("--check", metavar="FILE")
    a = ap.parse_args()
    block = table()
    if a.write:
        text = open(a.write).read()
        pre, _, post = split(text, a.write)
        open(a.write, "w").write(pre + block + post)
        print("status: wrote the table into " + a.write)
    elif a.check:
        _, old, _ = split(open(a.check).read(), a.check)
        if old != block:
            sys.stdout.write("status: %s's status table differs from the result files; "
                             "run `scripts/results status`.\n--- %s\n%s\n--- now\n%s\n" % (a.check, a.check, old, block))
            return 1
        print("status: %s's status table matches docs/results/" % a.check)
    else:
        print(block)
    return 0


if __name__ == "__main__":
    sys.exit(main())
