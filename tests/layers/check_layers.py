#!/usr/bin/env python3
"""Checks every include of the library's sources against the layer table of kernel/README.md.

A quoted include of a file in another layer is allowed only when that layer is listed under "may include" in the
including file's row; an include that names no layer folder, or a layer folder that the table lacks, is refused too.
Exits 1 and names every offending file, line and include; prints 'N passed, 0 failed' otherwise.
"""
import pathlib
import re
import sys

kernel = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "kernel")
table_row = re.compile(r"^\|\s*([a-z_]+)\s*\|[^|]*\|\s*([^|]*)\|\s*$")
allowed = {}
for line in (kernel / "README.md").read_text().splitlines():
    match = table_row.match(line)
    if match and match.group(1) != "layer":
        names = match.group(2).strip()
        allowed[match.group(1)] = set() if names == "-" else {n.strip() for n in names.split(",")}
if not allowed:
    sys.exit(f"{kernel / 'README.md'}: no layer table found")

quoted_include = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
checked = 0
problems = []
for source in sorted(kernel.rglob("*")):
    if source.suffix not in (".cpp", ".hpp") or "include" in source.relative_to(kernel).parts[:1]:
        continue
    layer = source.relative_to(kernel).parts[0]
    if layer not in allowed:
        problems.append(f"{source}: folder '{layer}' is not a layer of kernel/README.md")
        continue
    for number, text in enumerate(source.read_text().splitlines(), start=1):
        match = quoted_include.match(text)
        if not match:
            continue
        checked += 1
        target = match.group(1)
        target_layer = target.split("/")[0] if "/" in target else None
        if target_layer is None:
            problems.append(f"{source}:{number}: \"{target}\" names no layer folder")
        elif target_layer not in allowed:
            problems.append(f"{source}:{number}: \"{target}\" is in '{target_layer}', not a layer")
        elif target_layer != layer and target_layer not in allowed[layer]:
            problems.append(f"{source}:{number}: '{layer}' may not include '{target_layer}' (\"{target}\")")
        elif not (kernel / target).is_file():
            problems.append(f"{source}:{number}: \"{target}\" does not exist")

for problem in problems:
    print(problem)
print(f"{checked - len(problems)} passed, {len(problems)} failed")
sys.exit(1 if problems else 0)
