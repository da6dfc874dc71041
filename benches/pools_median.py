#!/usr/bin/env python3
"""The pools table of BENCHMARKS.md and the README, as the median of
several runs of `cargo bench --bench pools`.

    python3 benches/pools_median.py [RUNS] | python3 benches/splice.py pools

Each run is a new process: where its buffers land in memory moves the
memory limit itself by up to a third between runs (242 to 374 ns a
triangle on the medium pool), which no number of rounds inside one run
removes. Each cell of the printed table is the median of that cell over
RUNS runs (default 9); the last column gives the range of `draw_spans`
over the runs.
"""
import statistics
import subprocess
import sys

runs = int(sys.argv[1]) if len(sys.argv) > 1 else 9
tables = []
for _ in range(runs):
    out = subprocess.run(
        ["cargo", "bench", "--quiet", "--bench", "pools"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    rows = [line for line in out.splitlines() if line.startswith("| ")]
    header, body = rows[0], rows[1:]
    tables.append([[c.strip() for c in r.strip("|").split("|")] for r in body])


def number(cell):
    return float(cell.replace(",", ""))


def fmt(value, like):
    if "." in like:
        return f"{value:.2f}"
    return f"{round(value):,}"


cols = [c.strip() for c in header.strip("|").split("|")]
spans = cols.index("draw_spans")
print(header + " draw_spans over runs |")
print("|" + "---|" * (len(cols) + 1))
for i, first in enumerate(tables[0]):
    cells = first[:3]
    for j in range(3, len(first)):
        cells.append(fmt(statistics.median(number(t[i][j]) for t in tables), first[j]))
    seen = [number(t[i][spans]) for t in tables]
    cells.append(f"{min(seen):.2f} to {max(seen):.2f}")
    print("| " + " | ".join(cells) + " |")
