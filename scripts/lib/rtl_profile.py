#!/usr/bin/env python3
"""Sums callgrind's per-line counts of Verilated code by RTL instance (scripts/lib/rtl_profile.sh).

Usage: rtl_profile.py ANNOTATED.txt CYCLES DEPTH [ROWS]
ANNOTATED.txt is `callgrind_annotate --auto=yes --context=0` output over the Verilated sources;
CYCLES the simulated cycles of the profiled run (counts are divided by it); DEPTH 1 groups by
block (u_scanline_buffer), 2 by block and its next name (u_scanline_buffer.g_next). A statement
spans several lines: each counted line goes to the last instance named at or above it in the
same file, so the figures show where the cost is, not an exact account.
"""
import collections
import re
import sys

COUNT = re.compile(r'^\s*([\d,]+)\s+(\(\s*[\d.]+%\))?(.*)$')
BLOCK = r'watkins_top__DOT__((?:g_[a-z_]+__DOT__)?u_[a-z_]+?)'
PATTERNS = {
    1: re.compile(BLOCK + r'(?:__DOT__|\b)'),
    2: re.compile(r'watkins_top__DOT__((?:g_[a-z_]+__DOT__)?u_[a-z_]+?__DOT__[A-Za-z0-9_]+?)'
                  r'(?:__DOT__|__BRA|\b)'),
}


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    path, cycles, depth = argv[1], float(argv[2]), int(argv[3])
    rows = int(argv[4]) if len(argv) > 4 else 25
    if depth not in PATTERNS or cycles <= 0:
        sys.exit('rtl_profile.py: DEPTH is 1 or 2, CYCLES positive')
    pattern = PATTERNS[depth]
    totals = collections.Counter()
    source, last = None, '(eval and scheduling)'
    with open(path, encoding='utf-8', errors='replace') as f:
        for line in f:
            if line.startswith('-- Auto-annotated source:'):
                source = line.split(':', 1)[1].strip()
                last = '(eval and scheduling)'
                continue
            if source is None or '__DepSet_' not in source or source.endswith('__Slow.cpp'):
                continue
            m = COUNT.match(line)
            text = m.group(3).strip() if m else line
            named = pattern.search(text)
            if named:
                last = named.group(1).replace('__DOT__', '.')
            if m and not text.startswith('=>'):
                totals[last] += int(m.group(1).replace(',', ''))
    print(f"{'per cycle':>10}  instance")
    for name, count in totals.most_common(rows):
        print(f'{count / cycles:10.0f}  {name}')
    print(f'{sum(totals.values()) / cycles:10.0f}  (all Verilated code)')


if __name__ == '__main__':
    main(sys.argv)
