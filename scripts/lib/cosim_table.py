#!/usr/bin/env python3
"""docs/results/verify.md: the Verilated RTL against the bit-exact model on every shipped scene.

`watkins render SCENE --shading S --rtl [--sparse] [--config F]` for every scenes/*.json, Gouraud
and Phong, full-frame and sparse output, at the default configuration and, where
scenes/sized/<scene>.<shading>.json exists, at that sized configuration on the top built for it.
Each run compares every pixel of the RTL's frame with the model's and its cycles with the cycle
model's prediction; the model's error against the double reference comes from the same run.

    scripts/lib/cosim_table.py [--md FILE] [--header LINE] [--jobs N] [SCENE ...]

Without --md the page goes to stdout. Build: $WATKINS_BUILD or build/ (the watkins target with the
RTL, and the sized tops: WATKINS_RTL_CONFIGS).
"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("WATKINS_BUILD", os.path.join(ROOT, "build"))
WATKINS = os.path.join(BUILD, "watkins")


def run(scene, shading, config, sparse, tmp):
    """One `watkins render --rtl`: a dict of the figures, or the refusal."""
    cmd = [WATKINS, "render", "scenes/%s.json" % scene, "--shading", shading, "--rtl",
           "--out", os.path.join(tmp, "%s_%s_%s_%d.png" % (scene, shading, config, sparse))]
    if sparse:
        cmd.append("--sparse")
    if config == "sized":
        cmd += ["--config", "scenes/sized/%s.%s.json" % (scene, shading)]
    r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    o = r.stdout
    row = {"scene": scene, "shading": shading, "config": config, "output": "sparse" if sparse else "full-frame"}

    def grab(pattern):
        m = re.search(pattern, o, re.M)
        return m.groups() if m else None
    cycles = grab(r"^rtl cycles +(\d+)")
    predicted = grab(r"^rtl predicted (\d+) cycles")
    mism = grab(r"^rtl vs model +(\d+) mismatching")
    frags = grab(r"^fixed model .*?, (\d+) fragments")
    dbl = grab(r"^vs double +max \|d\| (\d+) levels, mean \|d\| ([0-9.]+)")
    stages = grab(r"^rtl stages +\d+ stage transfers compared, (\d+) diverging")
    if r.returncode == 2 or not cycles:
        msg = (r.stderr.strip().splitlines() or ["exit code %d" % r.returncode])[-1]
        row["refused"] = re.sub(r"^watkins: (error: )?", "", msg)
        return row
    row.update(cycles=int(cycles[0]), predicted=int(predicted[0]) if predicted else None,
               mismatches=int(mism[0]) if mism else None, fragments=int(frags[0]) if frags else None,
               double=dbl, stages=int(stages[0]) if stages else None, rc=r.returncode)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenes", nargs="*", help="scene names (default: every scenes/*.json)")
    ap.add_argument("--md")
    ap.add_argument("--header")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("WATKINS_JOBS", "2")))
    a = ap.parse_args()
    if not os.access(WATKINS, os.X_OK):
        sys.exit("cosim_table: no %s; build the watkins target first" % WATKINS)
    header = a.header or subprocess.run(
        ["bash", "-c", 'source "$0"; results_header "$1"', os.path.join(ROOT, "scripts", "lib", "results_header.sh"),
         "scripts/lib/cosim_table.py" + "".join(" " + x for x in sys.argv[1:])],
        capture_output=True, text=True, check=True).stdout.strip()
    scenes = a.scenes or sorted(f[:-5] for f in os.listdir(os.path.join(ROOT, "scenes")) if f.endswith(".json"))
    jobs = []
    for scene in scenes:
        for shading in ("gouraud", "phong"):
            configs = ["default"]
            if os.path.exists(os.path.join(ROOT, "scenes", "sized", "%s.%s.json" % (scene, shading))):
                configs.append("sized")
            for config in configs:
                for sparse in (0, 1):
                    jobs.append((scene, shading, config, sparse))
    with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        rows = list(pool.map(lambda j: run(*j, tmp), jobs))

    ran = [r for r in rows if "refused" not in r]
    clean = [r for r in ran if r["mismatches"] == 0 and r["stages"] == 0 and r["rc"] == 0]
    equal = [r for r in ran if r["cycles"] == r["predicted"]]
    refused = [r for r in rows if "refused" in r]
    out = [header, "",
           "# The RTL against the model",
           "",
           "`watkins render SCENE --shading S --rtl [--sparse] [--config scenes/sized/SCENE.S.json]` on every "
           "shipped scene (scenes/*.json), Gouraud and Phong, full-frame and sparse output: at the default "
           "configuration, and at the scene's sized configuration on the Verilated top built for it where "
           "scenes/sized/ has one. Each run feeds the prepared frame to the Verilated `watkins_top` (the plain "
           "C++ harness, no gaps or stalls), compares every pixel with the bit-exact model's image and every "
           "stage's stream with the model's, and compares the RTL's cycles (first edge beat offered to last "
           "pixel out) with the cycle model's prediction. The last column is the model's error against the "
           "double reference, in 8-bit levels over pixels showing the same polygon.",
           "",
           "%d frames on the RTL: %d with 0 mismatching pixels and no diverging stage, %d with cycles equal to "
           "the prediction%s." % (len(ran), len(clean), len(equal),
                                  "; %d not run (the configuration's top refuses the scene)" % len(refused)
                                  if refused else ""),
           "",
           "| scene | shading | configuration | output | fragments | mismatching pixels | diverging stages "
           "| RTL cycles | predicted | cycles = predicted | model vs double max / mean |",
           "|---|---|---|---|---:|---:|---:|---:|---:|---|---|"]
    for r in rows:
        if "refused" in r:
            out.append("| %s | %s | %s | %s | — | not run: %s | — | — | — | — | — |"
                       % (r["scene"], r["shading"], r["config"], r["output"], r["refused"].replace("|", "\\|")))
            continue
        d = r["double"]
        out.append("| %s | %s | %s | %s | %s | %s | %s | %d | %s | %s | %s |" % (
            r["scene"], r["shading"], r["config"], r["output"], r["fragments"], r["mismatches"], r["stages"],
            r["cycles"], r["predicted"], "yes" if r["cycles"] == r["predicted"] else "**no**",
            "%s / %s" % d if d else "—"))
    text = "\n".join(out) + "\n"
    if a.md:
        with open(a.md, "w") as f:
            f.write(text)
        print("cosim_table: wrote %s (%d frames, %d clean, %d cycles equal, %d not run)"
              % (a.md, len(ran), len(clean), len(equal), len(refused)))
    else:
        sys.stdout.write(text)
    return 0 if len(clean) == len(ran) == len(equal) else 1


if __name__ == "__main__":
    sys.exit(main())
