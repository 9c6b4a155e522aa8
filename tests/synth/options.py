#!/usr/bin/env python3
"""ctest synth_options (label synth): `watkins synth --nextpnr-options` reaches nextpnr and is
recorded. edge_incrementer on the iCE40 HX8K with an option nextpnr does not know: the row fails
with nextpnr's own message (so the words were passed to it), exit code 1, and the table and CSV
name the options used; an option the flow sets itself (--seed, --freq) is a usage error (exit 2)
before any tool runs. The flow's own options per target (none on iCE40, HeAP's timing weight on
the ECP5) are checked by synth_smoke and synth_seeds.
  options.py WATKINS WORK_DIR"""
import os
import shutil
import sys

from synth_check import Failures, synth

watkins, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
failures = Failures("synth_options")
check = failures.check

r, rows = synth(watkins, os.path.join(work, "bogus"), "--nextpnr-options", "--no-such-option")
check(r.returncode == 1, f"exit code {r.returncode} with a bad nextpnr option, expected 1")
check(len(rows) == 1, f"{len(rows)} rows, expected 1")
if rows:
    check(rows[0]["result"] == "failed (nextpnr): unrecognised option '--no-such-option'",
          f"result {rows[0]['result']!r}: nextpnr's message expected")
    check(rows[0]["nextpnr_options"] == "--no-such-option", f"CSV options {rows[0]['nextpnr_options']!r}")
check("nextpnr's placement options: ice40-hx8k `--no-such-option`." in r.stdout, "the table does not name the options")

for own in ("--seed 3", "--freq=200", "--placer sa --json x.json"):
    r, rows = synth(watkins, os.path.join(work, "own"), "--nextpnr-options", own)
    check(r.returncode == 2, f"--nextpnr-options {own!r}: exit code {r.returncode}, expected 2 (usage)")
    check("is set by watkins synth itself" in r.stderr, f"--nextpnr-options {own!r}: stderr {r.stderr.strip()!r}")
    check(not os.path.exists(os.path.join(work, "own")) and not rows, f"--nextpnr-options {own!r}: a tool ran")
failures.finish()
