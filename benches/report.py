#!/usr/bin/env python3
"""Prints a Markdown table of BENCHMARKS.md from criterion's results.

    python3 benches/report.py [triangles|pools|polygons|framebuffer] [TARGET_DIR]

Run after `cargo bench --bench NAME`; reads the median of each benchmark
from TARGET_DIR/criterion/<group>/<bench>/.../new/estimates.json.
"""
import json
import pathlib
import sys

BENCH = sys.argv[1] if len(sys.argv) > 1 else "triangles"
TARGET = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else pathlib.Path(__file__).resolve().parent.parent / "target"
ROOT = TARGET / "criterion"

SUITES = {
    # groups, (peer, column) pairs, ratio peers, unit
    "triangles": (
        ["4 px", "16 px", "64 px", "240 px", "mesh 320x240"],
        ["embedded-raster", "span fill", "embedded-graphics", "tiny-skia"],
        ["span fill", "embedded-graphics", "tiny-skia"],
        "tri",
    ),
    "pools": (
        ["pool tiny 4 px", "pool small 16 px", "pool medium 64 px", "pool large 240 px",
         "pool mesh 32x24 of 10 px"],
        ["limit", "draw", "draw_spans", "for_each_span", "EdgeWalk@12", "tiny-skia",
         "embedded-graphics"],
        [],
        "tri",
    ),
    "polygons": (
        ["hexagons 18 px (x60)", "random octagons 26 px (x60)", "convex 24-gon 200 px", "concave star 24 vertices 200 px",
         "pentagram 200 px (self-intersecting)"],
        ["fill", "triangulate and fill", "fill triangulated once", "tiny-skia"],
        ["triangulate and fill", "fill triangulated once", "tiny-skia"],
        "set",
    ),
}


def result(group, peer):
    """(median ns, pixels, count in the id or 1), or None if not run."""
    d = ROOT / group / peer
    runs = [p for p in d.rglob("new/estimates.json")] if d.exists() else []
    if not runs:
        return None
    new = runs[0].parent
    median = json.loads((new / "estimates.json").read_text())["median"]["point_estimate"]
    bench = json.loads((new / "benchmark.json").read_text())
    count = bench.get("value_str") or "1"
    elements = (bench.get("throughput") or {}).get("Elements", 0)
    return median, elements, int(count) if count.isdigit() else 1


if BENCH == "bands":
    # Time relative to the whole frame, per scene, and the pixel memory.
    print("| rows per band | pixel buffer (320 px wide, Rgb565) | demo scene: time ÷ whole frame | mesh scene: time ÷ whole frame |")
    print("|---|---|---|---|")
    whole = {n: result(f"bands {n}", "whole frame") for n in ["demo", "mesh"]}
    for rows in [1, 8, 16, 32, 240]:
        cells = []
        for n in ["demo", "mesh"]:
            r = result(f"bands {n}", "whole frame") if rows == 240 else result(f"bands {n}", "bands")
            if rows != 240:
                d = ROOT / f"bands {n}" / "bands" / str(rows) / "new" / "estimates.json"
                r = (json.loads(d.read_text())["median"]["point_estimate"],) if d.exists() else None
            cells.append("-" if r is None else f"{r[0] / whole[n][0]:.2f}x")
        label = "240 (whole frame)" if rows == 240 else str(rows)
        print(f"| {label} | {320 * rows * 2:,} B | " + " | ".join(cells) + " |")
    print(f"\nWhole frame: demo {whole['demo'][0] / 1e3:.1f} µs, mesh {whole['mesh'][0] / 1e3:.1f} µs per frame.")
    sys.exit(0)
if BENCH == "framebuffer":
    # embedded-graphics drawing on both framebuffers; "null" stores nothing.
    print("| drawing | embedded-raster µs | embedded-graphics µs | no stores µs | embedded-graphics time ÷ embedded-raster time |")
    print("|---|---|---|---|---|")
    for g in ["text transparent", "text on a background", "filled circles", "scattered pixels"]:
        r = {p: result("framebuffer " + g, p) for p in ["embedded-raster", "embedded-graphics", "null"]}
        us = lambda p: "-" if r[p] is None else f"{r[p][0] / 1e3:.1f}"
        print(f"| {g} | {us('embedded-raster')} | {us('embedded-graphics')} | {us('null')} "
              f"| {r['embedded-graphics'][0] / r['embedded-raster'][0]:.2f}x |")
    sys.exit(0)
groups, peers, ratios, unit = SUITES[BENCH]
first = peers[0]
if BENCH == "pools":
    # Each contender's speed as a fraction of the limit's (limit time / time).
    print("| pool | triangles | px each | limit ns/tri | " + " | ".join(peers[1:]) + " |")
    print("|---" * (3 + len(peers)) + "|")
    for g in groups:
        r = {p: result(g, p) for p in peers}
        ns, pixels, count = r[first]
        row = [g.removeprefix("pool "), str(count), f"{pixels / count:,.0f}", f"{ns / count:,.0f}"]
        row += ["-" if r[p] is None else f"{ns / r[p][0]:.2f}" for p in peers[1:]]
        print("| " + " | ".join(row) + " |")
    sys.exit(0)
print(f"| {BENCH} | px | " + " | ".join(f"{p} ns/{unit}" for p in peers)
      + f" | {first} Mpx/s | " + " | ".join(f"time ÷ {p}" for p in ratios) + " |")
print("|---" * (3 + len(peers) + len(ratios)) + "|")
for g in groups:
    r = {p: result(g, p) for p in peers}
    ns, pixels, count = r[first]
    row = [g if count == 1 else f"{g} (x{count})", f"{pixels / count:.0f}"]
    row += ["-" if r[p] is None else f"{r[p][0] / count:.0f}" for p in peers]
    row.append(f"{pixels / ns * 1e3:.0f}")
    row += ["-" if r[p] is None else f"{ns / r[p][0]:.2f}x" for p in ratios]
    print("| " + " | ".join(row) + " |")
