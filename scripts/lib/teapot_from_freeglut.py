#!/usr/bin/env python3
"""Writes scenes/teapot.json: Newell's teapot as 32 bicubic Bezier patches, with the control
points read from the installed freeglut library (Debian libglut3.12), which carries Newell's
public-domain data in its read-only data as one float array (x, y, z per point, z up) and one int
array (16 point indices per patch) for 10 patches: rim, upper body, lower body, lid (2), bottom,
handle (2), spout (2), each a quarter (x >= 0, y <= 0) or a half (y <= 0) of the surface.

Nothing here is copied from freeglut's source: the arrays are found by their shape, checked
against the teapot's geometry, and the whole teapot is rebuilt from its symmetry (the four
quarters of the rim, body, lid and bottom by x -> -x and y -> -y; the two halves of the handle and
spout by y -> -y). A copy mirrored once has its columns reversed so every patch keeps
dP/ds x dP/dt pointing out of the teapot; the copies' shared points are merged.

Usage: scripts/lib/teapot_from_freeglut.py [--lib PATH] [--out scenes/teapot.json]
"""
import argparse
import glob
import json
import math
import struct
import sys

POINTS, PATCHES = 129, 10  # in the library: the 10 input patches and the points they index
QUARTERS = 6               # the first 6 are quarters (x >= 0, y <= 0), the rest halves (y <= 0)


def float32_text(x):
    """Shortest decimal that reads back as the same float32 (2.4, not 2.4000000953674316)."""
    for digits in range(1, 10):
        s = '%.*g' % (digits, x)
        if struct.unpack('<f', struct.pack('<f', float(s)))[0] == x:
            v = float(s)
            return 0.0 if v == 0 else v
    raise ValueError(x)


def find_arrays(blob):
    """(points, patches): the int32 run of 160 indices using every point 0..128 exactly as a
    patch list does, and the float32 run of 129 points whose patches are the teapot's pieces."""
    ints = [(off, struct.unpack_from('<160i', blob, off)) for off in range(0, len(blob) - 640, 4)]
    for ioff, idx in ints:
        if min(idx) != 0 or max(idx) != POINTS - 1 or len(set(idx)) != POINTS:
            continue
        for foff in range(0, len(blob) - 12 * POINTS, 4):
            f = struct.unpack_from('<%df' % (3 * POINTS), blob, foff)
            if not all(math.isfinite(v) and abs(v) < 4 for v in f) or f[0:3] == (0.0, 0.0, 0.0):
                continue
            pts = [tuple(float32_text(v) for v in f[3 * i:3 * i + 3]) for i in range(POINTS)]
            patches = [idx[16 * p:16 * p + 16] for p in range(PATCHES)]
            if looks_like_teapot(pts, patches):
                return pts, patches, ioff, foff
    sys.exit('teapot data not found in the library')


def looks_like_teapot(pts, patches):
    """The quarters lie in x >= 0, y <= 0 and span the teapot's height 0..3.15 (z up); the
    halves reach out to the handle (x < -2.5) and the spout (x > 3.4)."""
    zs = [p[2] for p in pts]
    if min(zs) != 0 or max(zs) != 3.15:
        return False
    for i, patch in enumerate(patches):
        q = [pts[k] for k in patch]
        if any(p[1] > 0 for p in q) or (i < QUARTERS and any(p[0] < 0 for p in q)):
            return False
    xs = [pts[k][0] for patch in patches[QUARTERS:] for k in patch]
    return min(xs) < -2.5 and max(xs) > 3.4


def bezier(cp, s, t):
    """Point and partials of a bicubic Bezier patch (cp[4*row+col])."""
    def b(u):
        w = 1 - u
        return [w * w * w, 3 * u * w * w, 3 * u * u * w, u * u * u], [-3 * w * w, 3 * w * w - 6 * u * w,
                                                                      6 * u * w - 3 * u * u, 3 * u * u]
    bs, dbs = b(s)
    bt, dbt = b(t)
    p, ds, dt = [0.0] * 3, [0.0] * 3, [0.0] * 3
    for i in range(4):
        for j in range(4):
            for a in range(3):
                c = cp[4 * i + j][a]
                p[a] += bt[i] * bs[j] * c
                ds[a] += bt[i] * dbs[j] * c
                dt[a] += dbt[i] * bs[j] * c
    return p, ds, dt


def outward(cp):
    """Whether dP/ds x dP/dt at the patch's middle points away from the teapot's (z) axis."""
    p, ds, dt = bezier(cp, 0.5, 0.5)
    n = [ds[1] * dt[2] - ds[2] * dt[1], ds[2] * dt[0] - ds[0] * dt[2], ds[0] * dt[1] - ds[1] * dt[0]]
    return n[0] * p[0] + n[1] * p[1] > 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--lib', default=None)
    ap.add_argument('--out', default='scenes/teapot.json')
    args = ap.parse_args()
    lib = args.lib or sorted(glob.glob('/usr/lib/x86_64-linux-gnu/libglut.so.3*'))[-1]
    blob = open(lib, 'rb').read()
    pts, patches, ioff, foff = find_arrays(blob)

    points, index = [], {}

    def point(p):
        p = tuple(0.0 if v == 0 else v for v in p)  # -0.0 and 0.0 are one point
        if p not in index:
            index[p] = len(points)
            points.append(p)
        return index[p]

    out = []
    for i, patch in enumerate(patches):
        mirrors = [(1, 1), (-1, 1), (1, -1), (-1, -1)] if i < QUARTERS else [(1, 1), (1, -1)]
        for sx, sy in mirrors:
            q = [point((sx * pts[k][0], sy * pts[k][1], pts[k][2])) for k in patch]
            if sx * sy < 0:  # mirrored once: reverse each row to keep the front outside
                q = [q[4 * r + c] for r in range(4) for c in (3, 2, 1, 0)]
            out.append(q)
    # Every patch of the library's data faces the same way; turn them all out if they face in.
    # The body's 8 patches (copies of input patches 1 and 2) are checked one by one.
    body = [[points[k] for k in q] for q in out[4:12]]
    if not outward(body[0]):
        out = [[q[4 * r + c] for r in range(4) for c in (3, 2, 1, 0)] for q in out]
        body = [[points[k] for k in q] for q in out[4:12]]
    assert len(out) == 32 and all(outward(cp) for cp in body)

    pts_text = ',\n'.join('       [%s]' % ', '.join(json.dumps(v) for v in p) for p in points)
    patch_text = ',\n'.join('       [%s]' % ', '.join(str(k) for k in q) for q in out)
    scene = f'''{{
  // Newell's teapot (1975): 32 bicubic Bezier patches on {len(points)} distinct control points, z up in
  // the data (rotate_deg turns it y up). Generated by scripts/lib/teapot_from_freeglut.py from the
  // public-domain data the installed freeglut carries ({lib.split("/")[-1]}: {POINTS} points at file
  // offset {foff}, {PATCHES} patches of 16 indices at {ioff}): the rim, body, lid and bottom are
  // quarters mirrored in x and y, the handle and spout halves mirrored in y; points shared by the
  // copies merged. The lid's and bottom's patches have collapsed rows (a pole): their normals are
  // the limits from inside. Phong's rule; the silhouette is the polygon path's weak spot.
  // u = v = 4 (512 grid elements, 280 after culling) needs 64 active edges (scan line 73), the
  // default hardware's; u = v = 6 needs 90 (--max-active-edges 128). k_u, k_v: the interior edges
  // when drawn by curves (--patches curves): 4 x 4 subpatches per patch, at most 68 curved edges on
  // a line (k = 2: 42, k = 8: 134); the polygons are the u x v grid.
  "screen": {{"width": 320, "height": 240, "background": [10, 10, 16]}},
  "camera": {{"type": "lookat", "eye": [0.75, 6.6, -12.1], "target": [0.2, 1.4, 0], "up": [0, 1, 0], "fov_deg": 40,
             "near": 0.5, "far": 100}},
  "light": {{"type": "directional", "direction": [-1, 1.3, -1]}},
  "shading": {{"rule": "phong", "cull_backfaces": true}},
  "materials": {{"porcelain": {{"color": [0.85, 0.82, 0.72], "d": 0.2, "W": 0.6, "n": 40}}}},
  "objects": [
    {{"type": "patches", "basis": "bezier", "material": "porcelain", "u": 4, "v": 4, "k_u": 4, "k_v": 4,
     "rotate_deg": [-90, 0, 0],
     "control_points": [
{pts_text}
     ],
     "patches": [
{patch_text}
     ]}}
  ]
}}
'''
    open(args.out, 'w').write(scene)
    print(f'{args.out}: {len(out)} patches, {len(points)} control points from {lib}')


if __name__ == '__main__':
    main()
