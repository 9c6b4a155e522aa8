#!/usr/bin/env python3
"""The README's table of sized configurations: `watkins size` on every shipped scene, Gouraud and
Phong, at --bound 1 (or the bound given). Writes each configuration to scenes/sized/<scene>.<shading>.json
(or $WATKINS_SIZE_OUT) and prints a markdown table: per group int.frac, depth_bits, capacities,
edge-record and line-buffer bits, the error against the double reference at the chosen point and,
one bit below, which limit broke for each width.
  scripts/lib/size_table.py [--bound L]          (build: $WATKINS_BUILD or build/)
"""
import os
import platform
import re
import subprocess
import sys
import time

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
build = os.environ.get("WATKINS_BUILD", os.path.join(root, "build"))
out = os.environ.get("WATKINS_SIZE_OUT", os.path.join(root, "docs", "size"))
watkins = os.path.join(build, "watkins")
bound = "1"
if len(sys.argv) == 3 and sys.argv[1] == "--bound":
    bound = sys.argv[2]
elif len(sys.argv) != 1:
    sys.exit("usage: scripts/lib/size_table.py [--bound L]")
if not os.access(watkins, os.X_OK):
    sys.exit(f"size_table: no {watkins}; build the watkins target first")
os.makedirs(out, exist_ok=True)

scenes = sorted(f[:-5] for f in os.listdir(os.path.join(root, "scenes")) if f.endswith(".json"))
cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), platform.processor())
print(f"machine {os.cpu_count()} cores, {cpu}, {time.strftime('%Y-%m-%d', time.gmtime())}, --bound {bound}\n")
print("| scene | shading | x | depth (depth_bits) | shade / normal | active edges | max_width | materials | polygons "
      "| edge record bits | line buffer bits | chosen: max / mean \\|Δ\\| (default) | one bit below: what broke | s |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")


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
            print(f"| {scene} | {shading} | failed: {r.stderr.strip()} |")
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
              f"| {'; '.join(below)} | {secs:.2f} |", flush=True)
