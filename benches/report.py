#!/usr/bin/env python3
"""Prints the Markdown table of BENCHMARKS.md from criterion's results.

Run after `cargo bench --bench triangles`; reads the median of each
benchmark from target/criterion/<group>/<bench>/<n>/new/estimates.json.
"""
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent / "target" / "criterion"
GROUPS = ["4 px", "16 px", "64 px", "240 px", "mesh 320x240"]
PEERS = ["embedded-raster", "span fill", "embedded-graphics", "tiny-skia"]


def result(group, peer):
    d = ROOT / group / peer
    runs = [p for p in d.iterdir() if (p / "new" / "estimates.json").exists()]
    if len(runs) != 1:
        sys.exit(f"expected one result under {d}")
    run = runs[0]
    median = json.loads((run / "new" / "estimates.json").read_text())["median"]["point_estimate"]
    bench = json.loads((run / "new" / "benchmark.json").read_text())
    return median, bench["throughput"]["Elements"], int(run.name)


print("| triangles | px | " + " | ".join(f"{p} ns/tri" for p in PEERS)
      + " | embedded-raster Mpx/s | time ÷ span fill | time ÷ embedded-graphics | time ÷ tiny-skia |")
print("|---" * (2 + len(PEERS) + 4) + "|")
for g in GROUPS:
    r = {p: result(g, p) for p in PEERS}
    ns, pixels, count = r["embedded-raster"]
    row = [f"{g} (x{count})", f"{pixels / count:.0f}"]
    row += [f"{r[p][0] / count:.0f}" for p in PEERS]
    row.append(f"{pixels / ns * 1e3:.0f}")
    row += [f"{ns / r[p][0]:.2f}x" for p in ["span fill", "embedded-graphics", "tiny-skia"]]
    print("| " + " | ".join(row) + " |")
