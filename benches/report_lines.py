#!/usr/bin/env python3
"""Prints the "Lines" tables of BENCHMARKS.md from criterion's results:
1-pixel lines, then random thick lines.

Run after `cargo bench --bench lines`; reads the median of each benchmark
from <target>/criterion/<group>/<bench>/<n>/new/estimates.json, where
<target> is $CARGO_TARGET_DIR or ./target.
"""
import json
import os
import pathlib
import sys

TARGET = os.environ.get("CARGO_TARGET_DIR") or pathlib.Path(__file__).resolve().parent.parent / "target"
ROOT = pathlib.Path(TARGET) / "criterion"
GROUPS = ["lines 8 px", "lines 300 px", "lines cut"]
PEERS = ["bresenham", "dda", "naive", "embedded-graphics"]


def result(group, peer):
    d = ROOT / group / peer
    runs = [p for p in d.iterdir() if (p / "new" / "estimates.json").exists()]
    if len(runs) != 1:
        sys.exit(f"expected one result under {d}")
    run = runs[0]
    median = json.loads((run / "new" / "estimates.json").read_text())["median"]["point_estimate"]
    bench = json.loads((run / "new" / "benchmark.json").read_text())
    return median, bench["throughput"]["Elements"], int(run.name)


print("| lines | px/line | " + " | ".join(f"{p} ns/line" for p in PEERS)
      + " | " + " | ".join(f"{p} Mpx/s" for p in PEERS) + " | bresenham ÷ embedded-graphics |")
print("|---" * (2 + 2 * len(PEERS) + 1) + "|")
for g in GROUPS:
    r = {p: result(g, p) for p in PEERS}
    ns, pixels, count = r["bresenham"]
    row = [f"{g.removeprefix('lines ')} (x{count})", f"{pixels / count:.0f}"]
    row += [f"{r[p][0] / count:.0f}" for p in PEERS]
    row += [f"{pixels / r[p][0] * 1e3:.0f}" for p in PEERS]
    row.append(f"{ns / r['embedded-graphics'][0]:.2f}x")
    print("| " + " | ".join(row) + " |")

THICK = ["thick lines short", "thick lines long"]
THICK_PEERS = ["draw", "draw_spans", "tiny-skia", "embedded-graphics"]
if all((ROOT / g).exists() for g in THICK):
    print()
    print("| thick lines | px/line | limit ns/line | " + " | ".join(f"{p} ns/line" for p in THICK_PEERS)
          + " | " + " | ".join(f"{p} ÷ limit" for p in THICK_PEERS) + " | draw ÷ tiny-skia |")
    print("|---" * (3 + 2 * len(THICK_PEERS) + 1) + "|")
    for g in THICK:
        limit, pixels, count = result(g, "limit")
        r = {p: result(g, p)[0] for p in THICK_PEERS}
        row = [f"{g.removeprefix('thick lines ')} (x{count})", f"{pixels / count:.0f}", f"{limit / count:.0f}"]
        row += [f"{r[p] / count:.0f}" for p in THICK_PEERS]
        row += [f"{limit / r[p]:.2f}" for p in THICK_PEERS]
        row.append(f"{r['draw'] / r['tiny-skia']:.2f}x")
        print("| " + " | ".join(row) + " |")
