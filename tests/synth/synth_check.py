"""What the synth ctests share: one `watkins synth` run on edge_incrementer into a work folder
(its CSV table there), printed, with its rows; and failures collected, reported at the end."""
import csv
import os
import subprocess
import sys


def synth(watkins, work, *options, target="ice40-hx8k", env=None):
    """watkins synth --designs edge_incrementer --targets `target` `options` into `work`: the
    completed process and the CSV table's rows (none when it wrote no table)."""
    table = os.path.join(work, "synth.csv")
    r = subprocess.run([watkins, "synth", "--designs", "edge_incrementer", "--targets", target, "--work", work,
                        "--csv", table, "--timeout", "400", *options], capture_output=True, text=True, env=env)
    print(r.stdout, r.stderr)
    rows = list(csv.DictReader(open(table))) if os.path.exists(table) else []
    return r, rows


class Failures:
    def __init__(self, name):
        self.name, self.items = name, []

    def check(self, ok, what):
        if not ok:
            self.items.append(what)

    def finish(self):
        if self.items:
            sys.exit(f"{self.name}: " + "; ".join(self.items))
        print(f"{self.name}: OK")
