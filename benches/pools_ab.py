#!/usr/bin/env python3
"""A/B of the random pools: the working tree against another revision.

    python3 benches/pools_ab.py REV [RUNS]

Builds `benches/pools.rs` twice, at REV (in a temporary git worktree, with
a target directory of its own under target/) and from the working tree,
then runs the two executables in turn, RUNS times each (default 5), every
run the full interleaved bench with all its contenders. Prints, for each
pool and contender (the limit included), the median time a triangle
before and after and their ratio (after over before: below 1 is faster).

Why this way: the pools' times move with the machine over minutes, and
with where a process's buffers land, so two builds are only compared in
runs that alternate; and times, not fractions of the limit, since the
limit moves between processes as much as any contender (a contender the
change does not touch shows how much). And only the full bench counts: timed without the
other contenders between its rounds, one change looked 10 % faster on the
small pool and was 20 % slower in the full bench (BENCHMARKS.md, "Where a
triangle's instructions go").
"""
import statistics
import subprocess
import sys

from revisions import build_bench, root, worktree

rev = sys.argv[1]
runs = int(sys.argv[2]) if len(sys.argv) > 2 else 5


def table(exe):
    """One run's table: {(pool, contender): nanoseconds a triangle}, the
    limit's as printed, every other contender's as the limit's over its
    fraction of it."""
    out = subprocess.run([exe, "--bench"], check=True, capture_output=True, text=True).stdout
    rows = [l for l in out.splitlines() if l.startswith("| ")]
    cols = [c.strip() for c in rows[0].strip("|").split("|")]
    cells = {}
    for row in rows[1:]:
        values = [c.strip() for c in row.strip("|").split("|")]
        limit = float(values[3].replace(",", ""))
        cells[(values[0], "limit")] = limit
        for name, value in zip(cols[4:], values[4:]):
            cells[(values[0], name)] = limit / float(value)
    names = ["limit"] + cols[4:]
    return names, [r.strip("|").split("|")[0].strip() for r in rows[1:]], cells


with worktree(rev) as base:
    before = build_bench(base, root / "target" / "pools-ab-base", "pools")
    after = build_bench(root, root / "target", "pools")
    seen = {"before": [], "after": []}
    for _ in range(runs):
        for label, exe in (("before", before), ("after", after)):
            contenders, pools, cells = table(exe)
            seen[label].append(cells)

print(f"Nanoseconds a triangle, medians of {runs} alternating runs each: {rev} -> working tree.\n")
print("| pool | " + " | ".join(contenders) + " |")
print("|---|" + "---|" * len(contenders))
for pool in pools:
    cells = []
    for name in contenders:
        b = statistics.median(t[(pool, name)] for t in seen["before"])
        a = statistics.median(t[(pool, name)] for t in seen["after"])
        cells.append(f"{b:,.0f} -> {a:,.0f} ({a / b:.2f}x)")
    print(f"| {pool} | " + " | ".join(cells) + " |")
