#!/usr/bin/env python3
"""Replaces a generated table in README.md and BENCHMARKS.md.

    python3 benches/report.py pools | python3 benches/splice.py pools
    bash .ci/icount | python3 benches/splice.py icount

Reads a Markdown table (or block) on standard input and puts it between
the lines `<!-- NAME -->` and `<!-- /NAME -->` wherever they stand in
README.md and BENCHMARKS.md, so that the README shows exactly the measured
figures. Fails if no file has the markers.
"""
import pathlib
import re
import sys

name = sys.argv[1]
block = sys.stdin.read().strip("\n")
root = pathlib.Path(__file__).resolve().parent.parent
pattern = re.compile(
    rf"(<!-- {re.escape(name)} -->\n)(?:.*?\n)?(<!-- /{re.escape(name)} -->)", re.S
)
done = 0
for path in (root / "README.md", root / "BENCHMARKS.md"):
    text = path.read_text()
    new, n = pattern.subn(lambda m: m.group(1) + block + "\n" + m.group(2), text)
    if n:
        path.write_text(new)
        done += n
if not done:
    sys.exit(f"splice: no <!-- {name} --> markers found")
print(f"splice: {name}: {done} place(s)")
