#!/usr/bin/env python3
"""docs/results/compact_phong.md: Gouraud and Phong on the UP5K (compact top) beside Phong on the
ECP5 (pipelined top), on the same scenes.

Resources and routed Fmax: the two compact tops from `watkins synth` run here (--synth; else from
the files of an earlier run in docs/results/synth/compact_phong.{csv,head}), the pipelined Phong
top on the ECP5 from `scripts/synth phong` (docs/results/synth/phong.{csv,head}: a run of it
takes over an hour). The compact Phong top is synthesized at the narrow Phong formats when
rtl/watkins_top.sv takes them (`PhongNarrow`), else at the model's formats (the table says which).
Cycles: `watkins board check SCENE --board icebreaker|ulx3s --top T --shading S` (the cycle model
that equals each top's RTL clock for clock; each board check sizes the scene as `watkins size`
does for that top). Error: `watkins render SCENE --shading S --config C --truth` with C the
configuration `watkins size` writes for that top (`--compact` for the compact tops: the narrow
Phong formats), its `vs double` and `vs truth` lines (max and mean |d| in levels).
  compact_phong_results.py --md OUT --header LINE [--watkins BIN] [--results DIR] [--synth]
"""
import argparse
import csv
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# (label, shading, board, top, compact sizing)
SETUPS = [("Gouraud, UP5K (compact top)", "gouraud", "icebreaker", "compact", True),
          ("Phong, UP5K (compact top)", "phong", "icebreaker", "compact", True),
          ("Phong, ECP5 (pipelined top)", "phong", "ulx3s", "pipelined", False)]

ALONE = re.compile(r"^alone\s+(\d+) cycles a frame, (\d+) fragments \(([\d.]+) per clock\), slowest line (\d+): (\d+) clocks")
WORST = re.compile(r"^worst line\s+frame (\d+) line (\d+): slack (-?\d+)")
MISSED = re.compile(r"^missed\s+(\d+) lines")
BUDGET = re.compile(r"^budget\s+(\d+) pipeline clocks per rendered line")
CONFIG = re.compile(r"^config\s+(.*)$")
VS_DOUBLE = re.compile(r"^vs double\s+max \|d\| (\d+) levels, mean \|d\| ([\d.]+) levels")
VS_TRUTH = re.compile(r"^vs truth\s+fixed model: max \|d\| (\d+) levels, mean \|d\| ([\d.]+) levels")


def narrow_rtl():
    top = open(os.path.join(ROOT, "rtl", "watkins_top.sv")).read()
    return "PhongNarrow" in top and os.path.exists(os.path.join(ROOT, "rtl", "compact_phong_shader_narrow.sv"))


def run(cmd):
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)


def board_check(watkins, scene, shading, board, top, cfg=None):
    p = run([watkins, "board", "check", scene, "--board", board, "--top", top, "--shading", shading] +
            (["--config", cfg] if cfg else []))
    if p.returncode not in (0, 4):
        return {"error": (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]}
    got = {}
    for line in p.stdout.splitlines():
        for key, rx in (("alone", ALONE), ("worst", WORST), ("missed", MISSED), ("budget", BUDGET),
                        ("config", CONFIG)):
            m = rx.match(line)
            if m:
                got[key] = m.groups()
    return got


def error(watkins, scene, shading, compact, work, cfg=None):
    if not cfg:
        cfg = os.path.join(work, "config.json")
        p = run([watkins, "size", scene, "--shading", shading, "-o", cfg] + (["--compact"] if compact else []))
        if p.returncode != 0:
            return {"error": (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]}
    p = run([watkins, "render", scene, "--shading", shading, "--config", cfg,
             "-o", os.path.join(work, "image.png"), "--truth", os.path.join(work, "truth.png")])
    got = {}
    for line in p.stdout.splitlines():
        for key, rx in (("double", VS_DOUBLE), ("truth", VS_TRUTH)):
            m = rx.match(line)
            if m:
                got[key] = m.groups()
    return got


def synth(watkins, results, header):
    """Both compact tops on the UP5K, into results/synth/compact_phong.{md,csv,head}."""
    narrow = narrow_rtl()
    work = tempfile.mkdtemp()
    rows = []
    runs = [("top-compact", os.path.join("scenes", "sized", "default.gouraud.json"))]
    if narrow:
        cfg = os.path.join(work, "default.narrow.json")
        p = run([watkins, "size", "scenes/default.json", "--shading", "phong", "--compact", "-o", cfg])
        if p.returncode != 0:
            sys.exit("compact_phong_results: watkins size failed: " + p.stderr.strip())
        runs.append(("top-compact-phong", cfg))
    else:
        runs.append(("top-compact-phong", os.path.join("scenes", "sized", "default.phong.json")))
    commands = []
    for design, cfg in runs:
        cmd = [watkins, "synth", "--config", cfg, "--designs", design, "--targets", "ice40-up5k",
               "--work", os.path.join(os.environ.get("WATKINS_BUILD", os.path.join(ROOT, "build")), "synth"),
               "--csv", os.path.join(work, design + ".csv"), "--md", os.path.join(work, design + ".md")]
        if design == "top-compact-phong" and narrow:
            commands.append("watkins size scenes/default.json --shading phong --compact -o C")
            commands.append("watkins synth --config C " + " ".join(cmd[4:8]))
        else:
            commands.append("watkins synth " + " ".join(cmd[2:8]))
        print("compact_phong_results: " + commands[-1], flush=True)
        p = run(cmd)
        path = os.path.join(work, design + ".csv")
        if os.path.exists(path):
            rows += list(csv.DictReader(open(path)))
        else:
            print("compact_phong_results: %s: no result (%s)" % (design, p.stderr.strip()[-300:]), file=sys.stderr)
    if not rows:
        return
    out = os.path.join(results, "synth")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "compact_phong.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow(r)
    with open(os.path.join(out, "compact_phong.head"), "w") as f:
        f.write(header + "\n")
        f.write("Formats: %s\n" % ("narrow" if narrow else "model"))
        for c in commands:
            f.write("Command: `%s`\n" % c)


def read_csv(path, design, target):
    if not os.path.exists(path):
        return None
    for r in csv.DictReader(open(path)):
        if r["design"] == design and r["target"] == target and r["seed"] == "default":
            return r
    return None


def head_line(path):
    """The run's date and its formats, from a .head file (its first line names the commit)."""
    if not os.path.exists(path):
        return "", ""
    lines = open(path).read().splitlines()
    m = re.search(r", (\d{4}-\d\d-\d\d \d\d:\d\d UTC)\.$", lines[0]) if lines else None
    formats = next((l.split(": ", 1)[1] for l in lines if l.startswith("Formats: ")), "")
    return (m.group(1) if m else ""), formats


def resources(results):
    synth = os.path.join(results, "synth")
    cp_date, formats = head_line(os.path.join(synth, "compact_phong.head"))
    ph_date, _ = head_line(os.path.join(synth, "phong.head"))
    cp_commit = "`scripts/results compact-phong`, %s (synth/compact_phong.head)" % cp_date
    ph_commit = "`scripts/synth phong`, %s (synth/phong.head)" % ph_date
    fmt = {"narrow": "narrow Phong formats", "model": "the model's Phong formats (the narrow blocks not in the top yet)"}
    rows = [("Gouraud, UP5K (compact top)", "`top-compact`, `scenes/sized/default.gouraud.json` made compact",
             read_csv(os.path.join(synth, "compact_phong.csv"), "top-compact", "ice40-up5k"), cp_commit),
            ("Phong, UP5K (compact top)", "`top-compact-phong`, %s" % (
                "`watkins size --compact` of the default scene: " + fmt.get(formats, "?")),
             read_csv(os.path.join(synth, "compact_phong.csv"), "top-compact-phong", "ice40-up5k"), cp_commit),
            ("Phong, ECP5 (pipelined top)", "`top-phong`, `scenes/sized/default.phong.json`",
             read_csv(os.path.join(synth, "phong.csv"), "top-phong", "ecp5-85"), ph_commit)]
    out = ["| setup | design, configuration | logic cells | LUT4 | FF | DSP | block RAM | other RAM | routed Fmax MHz (constraint) | run (its commit in the .head file's first line) |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for label, what, r, commit in rows:
        if not r:
            out.append("| %s | %s | not run | | | | | | | |" % (label, what))
            continue
        f = float(r["fmax_mhz"] or 0)
        speed = ("%.1f (%s)" % (f, r["constraint_mhz"])) if f > 0 else r["result"]
        out.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            label, what, r["logic_cells"], r["lut4"], r["ff"], r["dsp"], r["bram"], r["ram_other"], speed, commit))
    return out


def fmt_err(e, key):
    v = e.get(key)
    return "%s, %s" % (v[0], v[1]) if v else "none"


def scenes_table(watkins):
    names = sorted(os.path.basename(p)[:-len(".phong.json")]
                   for p in glob.glob(os.path.join(ROOT, "scenes", "sized", "*.phong.json")))
    out = ["| scene | setup | cycles a frame | fragments | clocks per fragment | slowest line (clocks) | "
           "worst line's slack (clocks), lines missed | vs double: max, mean | vs truth: max, mean |",
           "|---|---|---|---|---|---|---|---|---|"]
    off, notes = [], []
    work = tempfile.mkdtemp()
    for name in names:
        scene = os.path.join("scenes", name + ".json")
        if not os.path.exists(os.path.join(ROOT, scene)):
            continue
        for label, shading, board, top, compact in SETUPS:
            c = board_check(watkins, scene, shading, board, top)
            e = error(watkins, scene, shading, compact, work)
            mark = ""
            if ("error" in c or "alone" not in c) and compact:
                # Where the board's own sizing fails: the scene's shipped sized configuration made
                # compact (and narrow for Phong), one lane.
                why = c.get("error", "no cycle figures").replace("watkins: error: ", "")
                cfg = os.path.join(work, "fallback.json")
                j = json.load(open(os.path.join(ROOT, "scenes", "sized", "%s.%s.json" % (name, shading))))
                j["compact"] = True
                j.pop("lanes", None)
                if shading == "phong":
                    j["phong"] = {"formats": "narrow"}
                json.dump(j, open(cfg, "w"))
                c = board_check(watkins, scene, shading, board, top, cfg)
                e = error(watkins, scene, shading, compact, work, cfg)
                mark = " *"
                if "alone" in c:
                    notes.append("`%s`, %s: %s; the row is at `scenes/sized/%s.%s.json` made compact%s" % (
                        name, label, why, name, shading, ", narrow" if shading == "phong" else ""))
            if "error" in c or "alone" not in c:
                off.append("`%s`, %s: %s" % (name, label, c.get("error", "no cycle figures").replace("watkins: error: ", "")))
                continue
            a = c["alone"]
            out.append("| %s | %s%s | %s | %s | %.2f | %s | %s, %s | %s | %s |" % (
                name, label, mark, format(int(a[0]), ","), format(int(a[1]), ","), int(a[0]) / max(1, int(a[1])),
                format(int(a[4]), ","), format(int(c["worst"][2]), ","),
                c["missed"][0], fmt_err(e, "double"), fmt_err(e, "truth")))
    return out, off, notes


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--md", required=True)
    ap.add_argument("--header", required=True)
    ap.add_argument("--watkins", default=os.path.join(os.environ.get("WATKINS_BUILD", os.path.join(ROOT, "build")),
                                                      "watkins"))
    ap.add_argument("--results", default=os.path.join(ROOT, "docs", "results"))
    ap.add_argument("--synth", action="store_true", help="synthesize the two compact tops on the UP5K first")
    a = ap.parse_args()
    if a.synth:
        synth(a.watkins, a.results, a.header)
    table, off, notes = scenes_table(a.watkins)
    text = [a.header, "",
            "# Phong on the UP5K",
            "",
            "The same scenes drawn three ways: Gouraud shading on the iCE40 UP5K (the compact top, "
            "docs/reference/compact.md), Phong shading on the UP5K (the compact top with the compact "
            "normalizer and shader, at the narrow Phong formats of docs/reference/compact-phong.md), "
            "and Phong shading on the ECP5-85 (the pipelined top).",
            "",
            "## Resources and routed speed",
            "",
            "`watkins synth` inside the wrapper that registers every input and output (its flip-flops "
            "included), nextpnr's default seed. The compact tops are run by `scripts/results "
            "compact-phong` (docs/results/synth/compact_phong.csv); the pipelined Phong top on the ECP5 "
            "comes from `scripts/synth phong` (docs/results/synth/phong.csv, a run of over an hour); "
            "the last column names each figure's run. Where a design does not fit, nextpnr packs it and "
            "stops before placing: the cells are the packed count.",
            ""] + resources(a.results) + [
            "",
            "## Cycles and error on the shipped scenes",
            "",
            "Cycles: `watkins board check SCENE --board B --top T --shading S` (B icebreaker for the "
            "compact top, one 25.125 MHz clock and 1,600 clocks a rendered line; ulx3s for the pipelined "
            "top, clk_pipe 78.75 MHz and 5,000 clocks a line), the cycle model that equals each top's RTL "
            "clock for clock: the frame alone from its first edge beat to its last pixel (edge records "
            "back to back, every pixel taken as it comes), its slowest line, then the frame racing the "
            "beam (worst slack, lines missed of 720). Clocks per fragment: the frame's cycles over its "
            "fragments. Error: `watkins render SCENE --shading S --config C --truth`, C from `watkins "
            "size SCENE --shading S` (`--compact` for the compact tops, which writes the narrow Phong "
            "formats), max and mean |d| in levels over the pixels showing the same polygon (the double "
            "reference) or object (the analytic truth; none where the scene's illumination is not "
            "Phong's eq. (3) or it has no exact surface).",
            ""] + table + [""]
    if notes:
        text += ["\\* The board check's sizing fails: " + "; ".join(notes) + ".", ""]
    if off:
        text += ["Not drawn: " + "; ".join(off) + ".", ""]
    open(a.md, "w").write("\n".join(text))
    print("compact_phong_results: wrote " + a.md)


if __name__ == "__main__":
    sys.exit(main())
