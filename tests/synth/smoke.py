#!/usr/bin/env python3
"""ctest synth_smoke (label synth): edge_incrementer through `watkins synth` on iCE40 HX8K -- yosys,
nextpnr-ice40 placement and routing -- in well under a minute. Asserts the row is routed with a
positive Fmax and a named critical path, and that the wrapper kept the block: its flip-flops are
more than the wrapper's own, and its adders left carry cells.
  smoke.py WATKINS WORK_DIR"""
import os
import shutil
import sys

from synth_check import Failures, synth

watkins, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
r, rows = synth(watkins, work, "--md", os.path.join(work, "synth.md"))
failures = Failures("synth_smoke")
check = failures.check

check(r.returncode == 0, f"exit code {r.returncode}")
check(len(rows) == 1, f"{len(rows)} rows in the table, expected 1")
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
    check(row["nextpnr_options"] == "", f"iCE40 placement options {row['nextpnr_options']!r}, expected none")
    check("nextpnr's placement options: ice40-hx8k none (nextpnr's defaults)." in r.stdout,
          "the table does not say which placement options ran")
    check("Yosys 0.23" in row["yosys_version"] or "Yosys" in row["yosys_version"], "yosys version not recorded")
failures.finish()
