#!/usr/bin/env python3
"""ctest synth_smoke (label synth): edge_incrementer through `watkins synth` on iCE40 HX8K -- yosys,
nextpnr-ice40 placement and routing -- in well under a minute. Asserts the row is routed with a
positive Fmax and a named critical path, and that the wrapper kept the block: its flip-flops are
more than the wrapper's own, and its adders left carry cells.
  smoke.py WATKINS WORK_DIR"""
import csv
import os
import shutil
import subprocess
import sys

watkins, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
table = os.path.join(work, "synth.csv")
r = subprocess.run([watkins, "synth", "--designs", "edge_incrementer", "--targets", "ice40-hx8k", "--work", work,
                    "--csv", table, "--md", os.path.join(work, "synth.md"), "--timeout", "100"],
                   capture_output=True, text=True)
print(r.stdout, r.stderr)
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


check(r.returncode == 0, f"exit code {r.returncode}")
rows = list(csv.DictReader(open(table))) if os.path.exists(table) else []
check(len(rows) == 1, f"{len(rows)} rows in {table}, expected 1")
if rows:
    row = rows[0]
    check(row["result"].startswith("routed"), f"result {row['result']!r}")
    check(float(row["fmax_mhz"] or 0) > 0, f"Fmax {row['fmax_mhz']!r}")
    check(row["path_start"] != "" and row["path_end"] != "", "critical path not named")
    check(row["logic_cells"].split(" / ")[-1].startswith("7680"), f"logic cells {row['logic_cells']!r} not of an HX8K")
    check(int(row["ff"]) > int(row["wrapper_ff"]) > 0, f"FF {row['ff']} vs wrapper FF {row['wrapper_ff']}: the block was lost")
    check(int(row["carry"]) > 0, "no carry cells: the block's adders were lost")
    check(row["seed"] == "default", f"seed {row['seed']!r}: none was given")
    check("| default | edge_incrementer | ice40-hx8k | default | routed" in r.stdout, "printed table lacks the row")
    check("Yosys 0.23" in row["yosys_version"] or "Yosys" in row["yosys_version"], "yosys version not recorded")
if failures:
    sys.exit("synth_smoke: " + "; ".join(failures))
print("synth_smoke: OK")
