#!/usr/bin/env python3
"""docs/guide/cli.md against the built `watkins`: the reference lists every subcommand (and every
subcommand of a subcommand, as `watkins board check`, in its own section), every option and every
positional argument that `watkins --help` and `watkins SUBCOMMAND [SUBCOMMAND] --help` print, and
nothing they do not; where --help prints a default, the reference's default column gives the same
value; the sweep's CSV column table names exactly the columns a sweep writes.

  check_cli_reference.py WATKINS SOURCE_DIR

Exit code 0 when the reference and the program agree, 1 otherwise, each disagreement on its own
line naming the subcommand and the option.
"""
import os
import re
import subprocess
import sys
import tempfile

DOC = os.path.join("docs", "guide", "cli.md")


def run_help(watkins, *args):
    r = subprocess.run([watkins, *args, "--help"], capture_output=True, text=True, timeout=60)
    if r.returncode != 0:
        sys.exit(f"{' '.join([watkins, *args])} --help: exit code {r.returncode}\n{r.stderr}")
    return r.stdout


NAME_COLUMN = 30  # CLI11 pads "  NAMES TYPE=DEFAULT" to this column and starts the description there


def help_sections(text):
    """CLI11's help: {'Options': [entry heads], 'Positionals': [...], 'Subcommands': [...]}. An entry
    starts at column 2; a head of 28 characters or more is alone on its line and its description
    follows on lines indented to NAME_COLUMN, a shorter head shares its line with the description."""
    sections, current = {}, None
    lines = text.splitlines()
    for i, line in enumerate(lines):
        m = re.match(r"^(\w[\w ]*):$", line)
        if m:
            current = sections.setdefault(m.group(1), [])
        elif current is not None and re.match(r"^  \S", line):
            alone = i + 1 < len(lines) and lines[i + 1].startswith(" " * NAME_COLUMN) and \
                len(line.rstrip()) >= NAME_COLUMN
            current.append(line.strip() if alone else line[:NAME_COLUMN].strip())
    return sections


def parse_options(entries):
    """{option name: default or None} for every name (short and long) of every option."""
    options = {}
    for head in entries:
        names, _, rest = head.partition(" ")
        default = None
        if "=" in rest:
            default = rest.rsplit("=", 1)[1]
            default = re.sub(r"\s+Excludes:.*$", "", default)  # CLI11 names the options it excludes
            default = re.sub(r"\s*\.\.\.$", "", default).strip()
            default = default[1:-1] if default.startswith("[") and default.endswith("]") else default
        for name in names.split(","):
            options[name] = default
    return options


def doc_sections(text):
    """{subcommand: section text} for every '## `watkins SUB`' or '## `watkins SUB NESTED`' heading."""
    parts = re.split(r"^## `watkins ([\w-]+(?: [\w-]+)?)`\s*$", text, flags=re.M)
    return {parts[i]: parts[i + 1] for i in range(1, len(parts), 2)}


def table_rows(section, first_header):
    """Rows (lists of cells) of the tables in `section` whose header's first cell is `first_header`."""
    rows, in_table = [], False
    for line in section.splitlines():
        if not line.startswith("|"):
            in_table = False
            continue
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]
        if not in_table:
            in_table = cells and cells[0] == first_header
            continue
        if all(re.fullmatch(r":?-+:?", c) for c in cells):
            continue
        rows.append(cells)
    return rows


def code_spans(cell):
    return re.findall(r"`([^`]+)`", cell)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    watkins, source = sys.argv[1], sys.argv[2]
    with open(os.path.join(source, DOC), encoding="utf-8") as f:
        doc = doc_sections(f.read())
    errors = []

    top = [e.split(" ")[0] for e in help_sections(run_help(watkins)).get("Subcommands", [])]
    if not top:
        sys.exit("watkins --help lists no subcommands")
    subcommands = []
    for sub in top:
        subcommands.append(sub)
        nested = help_sections(run_help(watkins, sub)).get("Subcommands", [])
        subcommands += [f"{sub} {e.split(' ')[0]}" for e in nested]
    for sub in subcommands:
        if sub not in doc:
            errors.append(f"{sub}: `watkins --help` lists it; {DOC} has no section '## `watkins {sub}`'")
    for sub in doc:
        if sub not in subcommands:
            errors.append(f"{sub}: {DOC} has a section for it; `watkins --help` lists no such subcommand")

    for sub in subcommands:
        if sub not in doc:
            continue
        sections = help_sections(run_help(watkins, *sub.split(" ")))
        options = parse_options(sections.get("Options", []))
        positionals = {e.split(" ")[0].upper() for e in sections.get("Positionals", [])}
        documented, doc_positionals = {}, set()
        for cells in table_rows(doc[sub], "option"):
            for span in code_spans(cells[0]):
                if span.startswith("-"):
                    documented[span] = cells[2] if len(cells) > 2 else ""
                elif re.fullmatch(r"[A-Z][A-Z_]*", span):
                    doc_positionals.add(span)
        if not documented:
            errors.append(f"{sub}: {DOC} has no option table (a table whose first column is 'option')")
        for name, default in options.items():
            if name not in documented:
                errors.append(f"{sub}: option {name} is in `watkins {sub} --help` but not in {DOC}'s {sub} table")
            elif default not in (None, "") and default not in code_spans(documented[name]):
                errors.append(f"{sub}: option {name}: --help gives the default `{default}`, {DOC} "
                              f"gives '{documented[name]}'")
        for name in documented:
            if name not in options:
                errors.append(f"{sub}: option {name} is in {DOC}'s {sub} table but not in `watkins {sub} --help`")
        for name in positionals - doc_positionals:
            errors.append(f"{sub}: positional argument {name} is in `watkins {sub} --help` but not in {DOC}'s {sub} table")
        for name in doc_positionals - positionals:
            errors.append(f"{sub}: positional argument {name} is in {DOC}'s {sub} table but not in `watkins {sub} --help`")

    # The sweep's CSV columns: the header of a one-point sweep (the cone, flat, its own tessellation).
    if "sweep" in doc and "sweep" in subcommands:
        documented = [code_spans(c[0])[0] for c in table_rows(doc["sweep"], "column") if code_spans(c[0])]
        with tempfile.TemporaryDirectory() as tmp:
            csv = os.path.join(tmp, "sweep.csv")
            r = subprocess.run([watkins, "sweep", os.path.join(source, "scenes", "cone.json"), "--shadings", "flat",
                                "--tess", "1", "--quiet", "--csv", csv], capture_output=True, text=True, timeout=300)
            if r.returncode != 0 or not os.path.exists(csv):
                errors.append(f"sweep: a one-point sweep failed (exit code {r.returncode}): {r.stderr.strip()}")
                written = documented
            else:
                with open(csv, encoding="utf-8") as f:
                    written = f.readline().strip().split(",")
        for column in written:
            if column not in documented:
                errors.append(f"sweep: CSV column {column} is written by `watkins sweep` but not in {DOC}'s column table")
        for column in documented:
            if column not in written:
                errors.append(f"sweep: CSV column {column} is in {DOC}'s column table but `watkins sweep` does not write it")

    for e in errors:
        print(e)
    print(f"{DOC}: {len(subcommands)} subcommands checked against --help, "
          f"{len(errors)} disagreement{'s' if len(errors) != 1 else ''}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
