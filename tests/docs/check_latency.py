#!/usr/bin/env python3
"""ctest docs_latency (label docs): the block latencies agree in three places.

  1. Each module's header in rtl/*.sv (the comment block above `module`) has exactly one sentence
     starting `Latency N` (N cycles, an integer) or `Latency:` and words (a latency that depends
     on the data or on a parameter).
  2. The block table of docs/reference/architecture.md has one row per rtl/ module, and no other;
     its latency cell starts with N, or with "variable" for a `Latency:` header. Every twin it
     names exists in model/twins/.
  3. Where the cycle model (model/twins/cycle_model.hpp, namespace rtl_timing) clocks a block, its
     constant equals the header's N: span_reciprocal, normalizer, phong_shader, rsqrt_unit
     (fmt::RsqrtStages), segment_interpolator (s0 + reciprocal + tail stages + span FIFO + stepper
     register), the smoother's stages, the Phong top's added cycles, and the two FIFO depths.

  check_latency.py [SOURCE_DIR]"""
import re
import sys
from pathlib import Path

root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]
failures = []


def fail(msg):
    failures.append(msg)


def header_of(sv):
    """The comment lines at the top of an rtl/ file, up to its first line of code, as one string."""
    lines = []
    for line in sv.splitlines():
        s = line.strip()
        if s.startswith("//"):
            lines.append(s[2:].strip())
        elif s == "":
            continue
        else:
            break
    return " ".join(lines)


def latency_sentence(module, header):
    """(kind, value, sentence): kind 'fixed' with the cycles, or 'variable'; None when malformed."""
    starts = [m.start() for m in re.finditer(r"\bLatency\b", header)]
    if len(starts) != 1:
        fail(f"rtl/{module}.sv: {len(starts)} sentences start with 'Latency' in the header, expected exactly one")
        return None
    rest = header[starts[0]:]
    end = re.search(r"\.(\s|$)", rest)
    sentence = rest[: end.start() + 1] if end else rest
    m = re.match(r"Latency (\d+)\b", sentence)
    if m:
        return "fixed", int(m.group(1)), sentence
    if sentence.startswith("Latency:"):
        return "variable", None, sentence
    fail(f"rtl/{module}.sv: the latency sentence must start 'Latency N' or 'Latency:', not {sentence[:60]!r}")
    return None


# ---- 1. the RTL headers
rtl = {}
for path in sorted((root / "rtl").glob("*.sv")):
    text = path.read_text()
    modules = re.findall(r"^module\s+(\w+)", text, re.M)
    if not modules:
        continue  # the package
    if modules != [path.stem]:
        fail(f"{path.relative_to(root)}: modules {modules}, expected one named {path.stem}")
    latency = latency_sentence(path.stem, header_of(text))
    if latency:
        rtl[path.stem] = latency

# ---- 2. the block table
doc_path = root / "docs" / "reference" / "architecture.md"
doc = doc_path.read_text()
table = None
lines = doc.splitlines()
for i, line in enumerate(lines):
    cells = [c.strip().lower() for c in line.strip().strip("|").split("|")]
    if line.startswith("|") and cells and cells[0] == "block" and any(c.startswith("latency") for c in cells):
        header = cells
        rows = []
        for row in lines[i + 2:]:
            if not row.startswith("|"):
                break
            rows.append([c.strip() for c in re.split(r"(?<!\\)\|", row.strip().strip("|"))])
        table = (header, rows)
        break
if table is None:
    fail(f"{doc_path.relative_to(root)}: no table with columns 'block' and 'latency'")
    header, rows = [], []
else:
    header, rows = table
lat_col = next((k for k, c in enumerate(header) if c.startswith("latency")), None)
twin_col = next((k for k, c in enumerate(header) if c.startswith("twin")), None)

doc_latency = {}
for cells in rows:
    m = re.fullmatch(r"`(\w+)`", cells[0])
    if not m:
        fail(f"architecture.md: block cell {cells[0]!r} is not one `module`")
        continue
    block = m.group(1)
    if block in doc_latency:
        fail(f"architecture.md: {block} has two rows")
    cell = cells[lat_col] if lat_col is not None and lat_col < len(cells) else ""
    doc_latency[block] = cell
    if twin_col is not None and twin_col < len(cells):
        for name in re.findall(r"`([\w.]+\.(?:hpp|cpp))`", cells[twin_col]):
            if not (root / "model" / "twins" / name).is_file():
                fail(f"architecture.md: {block}'s twin model/twins/{name} does not exist")

for block in sorted(set(rtl) - set(doc_latency)):
    fail(f"architecture.md: rtl/{block}.sv has no row in the block table")
for block in sorted(set(doc_latency) - set(rtl)):
    if not (root / "rtl" / f"{block}.sv").is_file():
        fail(f"architecture.md: block {block} has no rtl/{block}.sv")

for block, (kind, n, sentence) in sorted(rtl.items()):
    cell = doc_latency.get(block)
    if cell is None:
        continue
    if kind == "fixed":
        m = re.match(r"(\d+)\b", cell)
        if not m or int(m.group(1)) != n:
            fail(f"{block}: the header says {sentence[:70]!r}, the table's latency is {cell[:50]!r}")
    elif not cell.lower().startswith("variable"):
        fail(f"{block}: the header's latency depends on the data ({sentence[:70]!r}); "
             f"the table's cell must start 'variable', not {cell[:50]!r}")

# ---- 3. the cycle model's constants
formats = {name: int(value) for name, value in
           re.findall(r"X\((\w+),\s*(-?\d+),", (root / "model/twins/formats.hpp").read_text())}
cm_text = (root / "model/twins/cycle_model.hpp").read_text()
ns = re.search(r"namespace rtl_timing \{(.*?)\n\}", cm_text, re.S)
timing = {}
if not ns:
    fail("model/twins/cycle_model.hpp: no namespace rtl_timing")
else:
    for name, expr in re.findall(r"constexpr int (\w+) = ([^;]+);", ns.group(1)):
        e = re.sub(r"fmt::(\w+)", lambda m: str(formats[m.group(1)]), expr)
        e = re.sub(r"\b[A-Za-z_]\w*\b", lambda m: str(timing[m.group(0)]), e)
        if not re.fullmatch(r"[\d\s+\-*()]+", e):
            fail(f"cycle_model.hpp: cannot evaluate {name} = {expr}")
            continue
        timing[name] = eval(e)  # digits and + - * ( ) only


def fixed(block):
    entry = rtl.get(block)
    return entry[1] if entry and entry[0] == "fixed" else None


def expect(what, got, want):
    if got is None:
        fail(f"{what}: no fixed latency in its header to compare with the cycle model's {want}")
    elif got != want:
        fail(f"{what}: {got} in the RTL header, {want} in the cycle model")
    else:
        print(f"ok   {what}: {got}")


need = ["RecipStages", "InterpFifoDepth", "InterpTailStages", "NormalizerStages", "ShaderStages",
        "SmootherStages", "FragQueueDepth"]
if all(k in timing for k in need) and "RsqrtStages" in formats:
    expect("span_reciprocal = RecipStages", fixed("span_reciprocal"), timing["RecipStages"])
    expect("normalizer = NormalizerStages", fixed("normalizer"), timing["NormalizerStages"])
    expect("phong_shader = ShaderStages", fixed("phong_shader"), timing["ShaderStages"])
    expect("rsqrt_unit = fmt::RsqrtStages", fixed("rsqrt_unit"), formats["RsqrtStages"])
    if "DividerStages" in timing:
        expect("shade_divider = DividerStages", fixed("shade_divider"), timing["DividerStages"])
    fifo = fixed("stream_fifo")
    if fifo is not None:
        # s0, the reciprocal, sa .. sd, the span FIFO's write, the stepper's output register
        expect("segment_interpolator = 1 + RecipStages + InterpTailStages + stream_fifo + 1",
               fixed("segment_interpolator"), 1 + timing["RecipStages"] + timing["InterpTailStages"] + fifo + 1)
    # The smoother's latency depends on the frame (a pixel waits for its neighbours below), but
    # the count after the last of them is SmootherStages: its header and the table name it.
    smoother = rtl.get("smoother")
    want = timing["SmootherStages"]
    if smoother and not re.search(rf"\b{want} clocks\b", smoother[2]):
        fail(f"smoother: the header's latency sentence does not say '{want} clocks' (SmootherStages): {smoother[2][:90]!r}")
    elif smoother:
        print(f"ok   smoother: {want} clocks = SmootherStages")
    if not re.search(rf"\b{want} clocks\b", doc_latency.get("smoother", "")):
        fail(f"architecture.md: the smoother's latency cell does not say '{want} clocks' (SmootherStages)")
    # The Phong top's extra cycles: the normalizer's and the shader's stages.
    phong = timing["NormalizerStages"] + timing["ShaderStages"]
    top_header = header_of((root / "rtl/watkins_top.sv").read_text())
    for m in re.finditer(r"adding (\d+) cycles", top_header):
        if int(m.group(1)) != phong:
            fail(f"rtl/watkins_top.sv: the header says 'adding {m.group(1)} cycles' for Phong; "
                 f"NormalizerStages + ShaderStages = {phong}")
    if not re.search(rf"adds {phong}\b", doc_latency.get("watkins_top", "")):
        fail(f"architecture.md: watkins_top's latency cell does not say the Phong top adds {phong}")
    else:
        print(f"ok   Phong top adds {phong} = NormalizerStages + ShaderStages")
    # The FIFO depths the cycle model assumes.
    si = (root / "rtl/segment_interpolator.sv").read_text()
    m = re.search(r"parameter int unsigned FifoDepth\s*=\s*(\d+)", si)
    expect("segment_interpolator FifoDepth = InterpFifoDepth", int(m.group(1)) if m else None, timing["InterpFifoDepth"])
    top = (root / "rtl/watkins_top.sv").read_text()
    m = re.search(r"stream_fifo #\((?:(?!\) u_).)*?\.Depth\s*\(\s*(\d+)\s*\)(?:(?!\) u_).)*\) u_frag_queue", top, re.S)
    expect("watkins_top u_frag_queue Depth = FragQueueDepth", int(m.group(1)) if m else None, timing["FragQueueDepth"])
    cell = doc_latency.get("stream_fifo", "")
    row = next((r for r in rows if r and r[0] == "`stream_fifo`"), [])
    in_col = next((k for k, c in enumerate(header) if c == "in"), None)
    where = row[in_col] if in_col is not None and in_col < len(row) else ""
    for what, depth in (("span FIFO", timing["InterpFifoDepth"]), ("fragment queue", timing["FragQueueDepth"])):
        if f"{what} ({depth})" not in where:
            fail(f"architecture.md: stream_fifo's row does not say '{what} ({depth})'")
else:
    fail(f"cycle_model.hpp: rtl_timing lacks one of {need}, or formats.hpp RsqrtStages")

for block, (kind, n, _) in sorted(rtl.items()):
    print(f"{'ok  ' if block in doc_latency else 'FAIL'} {block}: {n if kind == 'fixed' else 'variable'}"
          f" | table: {doc_latency.get(block, '(no row)')[:60]}")
for f in failures:
    print(f"FAIL {f}")
print(f"docs_latency: {len(rtl)} modules, {len(failures)} failures")
sys.exit(1 if failures else 0)
