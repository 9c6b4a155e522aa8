#!/usr/bin/env python3
"""Writes scenes/two_lobed_16x16x12.u8.raw, the density volume scenes/voxel_file.json reads.

A stand-in for a reconstruction (Herman and Liu 1978): the two-lobed phantom of
model/scene/voxels.cpp as a density falling off linearly across its surface, 255 deep inside
and 0 far outside, so that threshold 128 keeps about the phantom itself. u8, x fastest, then y,
then z; 16 x 16 x 12 voxels of 1.04 x 1.04 x 1.68 (mm). Run from the repository root; the
file is committed, so this only documents (and can regenerate) it.
"""
import math
import sys

DIMS = (16, 16, 12)
SPACING = (1.04, 1.04, 1.68)
SIZE = (7.5, 7.5, 8.0)  # object units per unit-frame unit, as a phantom's "size"
BALLS = (((-0.4, -0.05, 0.0), 0.6), ((0.5, 0.1, 0.05), 0.48))  # voxels.cpp, TwoLobed


def density(p):
    q = [p[a] / SIZE[a] for a in range(3)]
    # Signed distance-like value in the unit frame: < 0 inside the union.
    d = min(math.dist(q, c) - r for c, r in BALLS)
    return max(0, min(255, round(128 - 400 * d)))


def main(out):
    data = bytearray()
    for k in range(DIMS[2]):
        for j in range(DIMS[1]):
            for i in range(DIMS[0]):
                p = [(n + 0.5 - 0.5 * DIMS[a]) * SPACING[a] for a, n in enumerate((i, j, k))]
                data.append(density(p))
    with open(out, "wb") as f:
        f.write(data)
    print(f"{out}: {len(data)} bytes")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "scenes/two_lobed_16x16x12.u8.raw")
