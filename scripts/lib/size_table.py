#!/usr/bin/env python3
"""docs/results/size.md: `watkins size` on every scene with a sized configuration in scenes/sized/,
Gouraud and Phong, at --bound 1 (or the bound given); each configuration rewritten in
scenes/sized/<scene>.<shading>.json. The table gives per group int.frac, depth_bits, capacities,
edge-record and line-buffer bits, the error against the double reference at the chosen point and,
one bit below, which limit broke for each width.
  scripts/lib/size_table.py [--bound L] [--all] [--md FILE] [--header LINE]
--all: every shipped scene (scenes/*.json); each file in scenes/sized/ gets a Verilated top in the
test build, so the set there stays small: give WATKINS_SIZE_OUT another folder with --all.
Without --md the page goes to stdout. Build: $WATKINS_BUILD or build/.
"""
import argparse
import os
import re
import subprocess
import sys
import time

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
build = os.environ.get("WATKINS_BUILD", os.path.join(root, "build"))
sized = os.path.join(root, "scenes", "sized")
out = os.environ.get("WATKINS_SIZE_OUT", sized)
watkins = os.path.join(build, "watkins")
ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--bound", default="1")
ap.add_argument("--all", action="store_true")
ap.add_argument("--md")
ap.add_argument("--header")
a = ap.parse_args()
bound = a.bound
if not os.access(watkins, os.X_OK):
    sys.exit(f"size_table: no {watkins}; build the watkins target first")
os.makedirs(out, exist_ok=True)
header = a.header or subprocess.run(
    ["bash", "-c", 'source "$0"; results_header "$1"', os.path.join(root, "scripts", "lib", "results_header.sh"),
     "scripts/lib/size_table.py" + "".join(" " + x for x in sys.argv[1:])],
    capture_output=True, text=True, check=True).stdout.strip()

shipped = sorted(f[:-5] for f in os.listdir(os.path.join(root, "scenes")) if f.endswith(".json"))
if a.all:
    scenes = shipped
else:
    with_file = {m.group(1) for f in os.listdir(sized) for m in [re.match(r"^(.*)\.(gouraud|phong)\.json$", f)] if m}
    scenes = [s for s in shipped if s in with_file]
page = open(a.md + ".part", "w") if a.md else sys.stdout  # renamed when every search ran
print(header, file=page)
print(f"""
# Sized configurations (`watkins size`)

`watkins size SCENE --shading S --bound {bound}` on every scene with a file in
[scenes/sized/](../../scenes/sized/), which this run rewrites: the smallest configuration whose image
stays within {bound} level{"" if bound == "1" else "s"} of the double reference (where the default configuration already differs
more, no worse than it), found by lowering one width at a time in four orders
([docs/guide/sizing.md](../guide/sizing.md)). Columns: int.frac per group; capacities; bits; the
error against the double reference at the chosen point (the default configuration's in brackets);
one bit below each width, which limit broke and the max |Δ| there ("invalid": below the
configuration's minimum); the search's wall time in seconds. `patches.curves.phong.json` is one
configuration for the patch scenes drawn by curves, not a row here.
""", file=page)
print("| scene | shading | x | depth (depth_bits) | shade / normal | active edges | max_width | materials | polygons "
      "| edge record bits | line buffer bits | chosen: max / mean \\|Δ\\| (default) | one bit below: what broke | s |",
      file=page)
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|", file=page)


def grab(pattern, text, group=1):
    m = re.search(pattern, text, re.M)
    if not m:
        raise SystemExit(f"size_table: no match for {pattern!r} in:\n{text}")
    return m.group(group)


short = {"x.frac_bits": "x", "shade.frac_bits": "shade", "normal.frac_bits": "normal", "depth_bits": "depth_bits",
         "depth.frac_bits": "depth"}
for scene in scenes:
    for shading in ("gouraud", "phong"):
        cfg = os.path.join(out, f"{scene}.{shading}.json")
        t0 = time.time()
        r = subprocess.run([watkins, "size", os.path.join(root, "scenes", scene + ".json"), "--shading", shading,
                            "--bound", bound, "--out", cfg], capture_output=True, text=True)
        secs = time.time() - t0
        if r.returncode != 0:
            print(f"| {scene} | {shading} | failed: {r.stderr.strip()} |", file=page, flush=True)
            continue
        t = r.stdout
        group = lambda g: grab(rf"^\s+{g}\s+(\S+)\s+(\d+)", t)
        attr = "normal" if shading == "phong" else "shade"
        caps = re.search(r"max_active_edges (\d+), max_width (\d+).*max_materials (\d+).*max_polygons (\d+)", t)
        chosen = re.search(r"^error chosen  max \|d\| (\d+), mean \|d\| ([0-9.]+)", t, re.M)
        default = re.search(r"^error default max \|d\| (\d+), mean \|d\| ([0-9.]+)", t, re.M)
        below = []
        for m in re.finditer(r"^  (\S+)\s+(-?\d+): (.*)\n(?:\s+broke (\w+))?", t, re.M):
            name, bits, first, what = m.group(1), m.group(2), m.group(3), m.group(4)
            if first.startswith("refused"):
                below.append(f"{short[name]} {bits}: invalid")
            else:
                mx = re.match(r"max \|d\| (\d+)", first).group(1)
                below.append(f"{short[name]} {bits}: {what} (max {mx})")
        depth_bits = grab(r"depth_bits (\d+)", t)
        edge_bits = grab(r"^edge record   (\d+)", t)
        line_bits = grab(r"^line buffer   (\d+)", t)
        print(f"| {scene} | {shading} | {group('x')} | {group('depth')} ({depth_bits}) "
              f"| {group(attr)} | {caps.group(1)} | {caps.group(2)} | {caps.group(3)} | {caps.group(4)} "
              f"| {edge_bits} | {line_bits} "
              f"| {chosen.group(1)} / {chosen.group(2)} ({default.group(1)} / {default.group(2)}) "
              f"| {'; '.join(below)} | {secs:.2f} |", file=page, flush=True)
if a.md:
    page.close()
    os.replace(a.md + ".part", a.md)
