#!/usr/bin/env python3
"""docs/results/bench.md and bench.csv from one `scripts/bench` run (its printed lines in a file).

Every figure in the table is one line of that run, so the ratios beside it were measured side by
side on the same machine at the same load; the product's speed targets are shown with each figure.
bench.csv holds the same figures one per row (key, value, unit) for scripts/lib/status.py.
  scripts/lib/bench_table.py BENCH_LOG [--out bench.md] [--csv bench.csv] [--header LINE]
"""
import argparse
import csv
import re
import sys


def model_rows(lines):
    """Per scene block of watkins_bench: fixed, new image, double, Mesa (M fragments/s), the two-thread
    pair (fixed2, mesa2) and GL's image against the model's (levels)."""
    blocks, cur = [], None
    for line in lines:
        m = re.match(r"^(phong: )?scene {3,}(.*)$", line)
        if m:
            if cur is not None and cur["phong"] and m.group(1) and cur["scene"].split(" (")[0] == m.group(2).split(" (")[0]:
                continue  # the GL half of the Phong block names the scene again
            cur = {"phong": bool(m.group(1)), "scene": m.group(2)}
            blocks.append(cur)
            continue
        if cur is None:
            continue
        body, two = line, False
        if body.startswith("phong: "):
            body = body[len("phong: "):]
        if body.startswith("2 threads: "):
            body, two = body[len("2 threads: "):], True
        for key, label in (("fixed", "fixed-point model"), ("new", "model, new image"),
                           ("double", "double reference"), ("mesa", "mesa gl")):
            m = re.match(r"^%s +[0-9.]+ ms/frame +([0-9.]+) M fragments/s" % re.escape(label), body)
            if m:  # a pair run in several rounds: its best
                k = key + ("2" if two else "")
                cur[k] = max(cur.get(k, 0.0), float(m.group(1)))
        m = re.match(r"^gl against model +max \|d\| (\d+) levels, mean \|d\| ([0-9.]+) levels, (\d+) pixels > 1 level \(of (\d+) both", body)
        if m:
            cur["gl_diff"] = m.groups()
    return blocks


def scene_name(text):
    if text.startswith("<default scene>"):
        return "default scene"
    m = re.match(r"grid (\d+x\d+), (\d+) triangles", text)
    return "grid %s, %s triangles" % m.groups() if m else text.split(" (")[0]


def fmt(v):
    return "%.1f M" % v if v is not None else "—"


def verilator_key(what, unit):
    """A stable key for a Verilator line: harness (cc, sc, sc_fast), top and, for instruction
    counts, whether the stage checker ran."""
    harness = "cc" if what.startswith("plain C++") else "sc_fast" if "speed build" in what else "sc"
    top = "phong" if "phong top" in what else "gouraud"
    if unit == "cycles/s":
        return "verilator.%s.%s" % (harness, top)
    checker = ".no_checker" if "no stage checker" in what else ".checker"
    return "verilator_ipc.%s.%s%s" % (harness, top, checker if harness == "cc" else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("log")
    ap.add_argument("--out", help="markdown file (default: stdout)")
    ap.add_argument("--csv", help="CSV of every figure: key, value, unit")
    ap.add_argument("--header", help="first line of the markdown file (scripts/lib/results_header.sh)")
    a = ap.parse_args()
    lines = [l.rstrip("\n") for l in (sys.stdin if a.log == "-" else open(a.log))]
    figures = []  # (key, value, unit)
    out = []
    if a.header:
        out += [a.header, ""]
    load0 = next((m.group(1) for l in lines for m in [re.search(r", load ([0-9.]+)$", l)] if l.startswith("machine ") and m), "?")
    load1 = next((m.group(1) for l in lines for m in [re.match(r"^load at the end +([0-9.]+)", l)] if m), "?")
    out += ["# Benchmarks (`scripts/bench`)", "",
            "Every figure is one line of one `scripts/bench` run, so the ratios are measured side by side on "
            "one machine at one load. Wall-clock figures (fragments/s, cycles/s) depend on the machine and "
            "on what else runs; instruction counts (callgrind) are repeatable. The model renders into one "
            "image reused across frames unless the row says \"a new image per frame\"; Mesa is llvmpipe "
            "through OSMesa on the same triangles, one thread unless the row says two (the model then draws "
            "bands of scan lines on two threads, the same image). The model's span kernel is the widest "
            "the processor has (AVX-512 or AVX2, chosen at run time); callgrind, which runs no AVX-512, "
            "counts the AVX2 kernel. Each model-and-Mesa pair runs in several rounds, one after the other, "
            "and each figure is its best round.", "",
            "Load average (1 minute) at the start of the run: %s; at its end: %s." % (load0, load1), "",
            "| what | figure | target |",
            "|---|---|---|"]
    instr = {m.group(2): m.group(1) for l in lines
             for m in [re.match(r"^model instructions +(\d+) per fragment \(callgrind, (.*)\)$", l)] if m}
    for b in model_rows(lines):
        name = scene_name(b["scene"])
        shading = "Phong" if b["phong"] else "Gouraud"
        key = "default" if name == "default scene" else re.sub(r"[^a-z0-9]+", "_", name.split(",")[0])
        fixed = b.get("fixed")
        parts = ["**%s fragments/s**" % fmt(fixed)]
        if "new" in b:
            parts.append("%s with a new image per frame" % fmt(b["new"]))
        parts.append("double reference %s" % fmt(b.get("double")))
        peer = "Mesa llvmpipe, GLSL eq. (3) per pixel, one thread" if b["phong"] else "Mesa llvmpipe, one thread"
        ratio = None
        if "mesa" in b:
            parts.append("%s %s" % (peer, fmt(b["mesa"])))
            if fixed:
                ratio = fixed / b["mesa"]
                parts.append("**model / Mesa %.2f×**" % ratio)
                figures.append(("model_over_mesa.%s.%s" % (shading.lower(), key), "%.3f" % ratio, "ratio"))
        if "gl_diff" in b:
            mx, mean, over, both = b["gl_diff"]
            parts.append("GL image against the model's: max \\|d\\| %s levels, mean %s, %s of %s pixels > 1 level" % (mx, mean, over, both))
            figures.append(("gl_image_max_abs.%s.%s" % (shading.lower(), key), mx, "levels"))
        ikey = "default scene" if name == "default scene" else "--grid 32"
        if not b["phong"] and ikey in instr:
            parts.append("%s instructions per fragment (callgrind)" % instr[ikey])
            figures.append(("instructions_per_fragment.%s" % key, instr[ikey], "instructions/fragment"))
        for k in ("fixed", "new", "double", "mesa", "fixed2", "mesa2"):
            if b.get(k) is not None:
                figures.append(("%s.%s.%s" % ({"fixed": "model", "new": "model_new_image", "fixed2": "model_2_threads",
                                               "mesa2": "mesa_2_threads"}.get(k, k), shading.lower(), key), b[k], "M fragments/s"))
        want = 1.0 if b["phong"] else 1.5
        verdict = ("met" if ratio is not None and ratio >= want else "not met") + " (model / Mesa ≥ %.1f×)" % want
        out.append("| model, %s, %s | %s | %s |" % (shading, name, "; ".join(parts), verdict))
        if b.get("fixed2") and b.get("mesa2"):
            r2 = b["fixed2"] / b["mesa2"]
            figures.append(("model_over_mesa_2_threads.%s.%s" % (shading.lower(), key), "%.3f" % r2, "ratio"))
            out.append("| model, %s, %s, two threads | **%s fragments/s** (bands of scan lines); Mesa llvmpipe, LP_NUM_THREADS=2, %s; **model / Mesa %.2f×** | %s (≥ 1.5×) |"
                       % (shading, name, fmt(b["fixed2"]), fmt(b["mesa2"]), r2, "met" if r2 >= 1.5 else "not met"))
    verilator = [m.groups() for l in lines
                 for m in [re.match(r"^verilator (.*?) +(\d+) (cycles/s|instructions/cycle)$", l)] if m]
    for what, value, unit in verilator:
        figures.append((verilator_key(what, unit), value, unit))
    # The SystemC bench's speed build (no assertions, no tracing) is the one the 1 M cycles/s target
    # is for; its row shows the assertion build's figure (the tests' bench) beside it. Logs without
    # a speed build: the assertion build's row carries the target.
    speed_sc = {re.sub(r" \(speed build;", " (assertions;", w): int(v) for w, v, u in verilator
                if u == "cycles/s" and "SystemC" in w and "(speed build;" in w}
    for what, value, unit in verilator:
        target = ""
        if unit == "cycles/s":
            v = int(value)
            if what in speed_sc:
                continue  # shown beside the speed build's figure
            figure = "**%.2f M cycles/s** (wall)" % (v / 1e6)
            if "SystemC" in what and "(speed build;" in what:
                twin = re.sub(r" \(speed build;", " (assertions;", what)
                asserting = next((int(x) for w, x, u in verilator if w == twin and u == "cycles/s"), None)
                if asserting is not None:
                    figure += "; assertion build (the tests' bench) %.2f M" % (asserting / 1e6)
            if "plain" in what and "gouraud" in what:
                target = ("met" if v >= 2_500_000 else "not met") + " (≥ 2.5 M, stage checker on)"
            elif "SystemC" in what and "gouraud" in what:
                target = ("met" if v >= 1_000_000 else "not met") + " (≥ 1 M)"
            out.append("| Verilator, %s | %s | %s |" % (what, figure, target))
        else:
            out.append("| Verilator, %s | %s instructions per simulated cycle (callgrind) | |" % (what, value))
    ipc = {m.group(1): int(m.group(2)) for l in lines
           for m in [re.match(r"^verilator plain C\+\+ harness, (gouraud|phong) top, stage checker on +(\d+) inst", l)] if m}
    if len(ipc) == 2:
        r = ipc["phong"] / ipc["gouraud"]
        figures.append(("verilator_ipc.phong_over_gouraud", "%.3f" % r, "ratio"))
        out.append("| Verilator, Phong top against Gouraud top (instructions per cycle, stage checker on) | %.2fx | %s (≤ 1.20x) |"
                   % (r, "met" if r <= 1.2 else "not met"))
    # The virtual board (scripts/lib/bench/board.sh): frames per second against the 1 frame/s target,
    # with its instructions per simulated clock.
    board_ipc = {m.group(1): (m.group(2), m.group(3)) for l in lines
                 for m in [re.match(r"^virtual board (\S+) +(\d+) instructions per (pipeline clock|clock) ", l)] if m}
    for l in lines:
        m = re.match(r"^virtual board (\S+) +([0-9.]+) frames/s, (\d+) (pipeline clocks|clocks)/s", l)
        if not m:
            continue
        board, fps, rate, unit = m.group(1), float(m.group(2)), int(m.group(3)), m.group(4)
        figures += [("virtual_board.%s.fps" % board, m.group(2), "frames/s"),
                    ("virtual_board.%s.clocks_per_second" % board, rate, "%s/s" % unit)]
        figure = "**%.2f frames/s** (wall, best of 5), %.2f M %s/s" % (fps, rate / 1e6, unit)
        if board in board_ipc:
            ipc, per = board_ipc[board]
            figures.append(("virtual_board.%s.instructions_per_clock" % board, ipc, "instructions/%s" % per))
            figure += "; %s instructions per %s (callgrind)" % (ipc, per)
        top = "ulx3s_top, pipelined" if board == "ulx3s" else "icebreaker_top, compact"
        out.append("| virtual board (`watkins board sim`), %s (%s), default scene | %s | %s (≥ 1 frame/s) |"
                   % (board, top, figure, "met" if fps >= 1 else "not met"))
    for l in lines:
        m = re.match(r"^shipped scenes +model at least as fast as the double reference on (\d+) of (\d+) \(scene, shading\); closest (.*) ([0-9.]+)x$", l)
        if m:
            held, total = int(m.group(1)), int(m.group(2))
            figures += [("shipped_scenes.model_not_slower", held, "pairs"), ("shipped_scenes.pairs", total, "pairs"),
                        ("shipped_scenes.closest_ratio", m.group(4), "ratio")]
            out.append("| model against the double reference, every shipped scene, both shadings | at least as fast on %d of %d; closest %s (%sx) | %s (never slower) |"
                       % (held, total, m.group(3), m.group(4), "met" if held == total else "not met"))
    for l in lines:
        m = re.match(r"^icarus speed +(\d+) cycles/s", l)
        if m:
            figures.append(("icarus.default", m.group(1), "cycles/s"))
            out.append("| Icarus Verilog (yosys-elaborated RTL), default scene | %s k cycles/s | |" % (int(m.group(1)) / 1e3))
    frames = [l for l in lines if re.match(r"^\S+ (gouraud|phong)( sparse)? +\d+ ", l)]
    if frames:
        out.append("")
        out.append("| RTL frame (Verilated, `watkins render --rtl`) | cycles | fragments | fragments/cycle | pixels/cycle | mismatches |")
        out.append("|---|---|---|---|---|---|")
        for l in frames:
            f = l.split()
            name = " ".join(f[:-5])
            figures.append(("rtl_frame.%s.cycles" % name.replace(" ", "."), f[-5], "cycles"))
            out.append("| %s | %s |" % (name, " | ".join(f[-5:])))
    text = "\n".join(out) + "\n"
    if a.out:
        open(a.out, "w").write(text)
    else:
        sys.stdout.write(text)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(["key", "value", "unit"])
            w.writerows(figures)


if __name__ == "__main__":
    main()
