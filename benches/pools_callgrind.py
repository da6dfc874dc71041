#!/usr/bin/env python3
"""Instructions a triangle for the random pools, counted by callgrind.

    python3 benches/pools_callgrind.py [--rev REV] [--contenders a,b,...]

Builds `benches/pools_pass.rs` and runs it under `valgrind --tool=callgrind`
for each pool and contender, once with 1 pass and once with 3; the
difference over two passes, divided by the pool's triangles, is the
contender's instructions a triangle (x86-64, or whatever this machine
is), without the pool's preparation. Prints them as a Markdown table,
with the limit's count over each contender's (the fraction of the
limit's work, in instructions). With `--rev`, also builds REV in a
temporary git worktree and prints REV -> working tree for each cell (REV
runs today's `benches/pools_pass.rs`, the pools and contenders of its own
`benches/common/pools.rs`).

Counts are exact and repeatable: they do not move with the machine's
load, so they show a change to the fill that times (`benches/pools.rs`,
`benches/pools_ab.py`) can only show in many alternating runs. They are
not times: a division or a mispredicted branch counts as one
instruction. Installs valgrind if it is missing.
"""
import argparse
import re
import shutil
import subprocess
import sys

from revisions import build_bench, root, worktree

POOLS = 5
ALL = ["limit", "draw", "draw_spans", "for_each_span", "EdgeWalk@12", "tiny-skia", "embedded-graphics"]

parser = argparse.ArgumentParser()
parser.add_argument("--rev")
parser.add_argument("--contenders", default=",".join(ALL))
args = parser.parse_args()
names = args.contenders.split(",")
if "limit" not in names:
    names.insert(0, "limit")

if shutil.which("valgrind") is None:
    subprocess.run(["apt-get", "update"], check=True, capture_output=True)
    subprocess.run(["apt-get", "install", "-y", "valgrind"], check=True, capture_output=True)


def instructions(exe, pool, name, passes):
    """Instructions callgrind counts in one run of `exe`, and the pool's
    name and number of triangles as `exe` prints them."""
    run = subprocess.run(
        ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
         exe, str(pool), name, str(passes)],
        check=True, capture_output=True, text=True,
    )
    m = re.search(r"Collected : (\d+)", run.stderr)
    p = re.search(r"^pool\t(.*)\t(\d+)$", run.stdout, re.M)
    if not m or not p:
        sys.exit(f"pools_callgrind: no count in\n{run.stderr}\n{run.stdout}")
    return int(m.group(1)), p.group(1), int(p.group(2))


def counts(exe):
    """{(pool, contender): instructions a triangle} and the pools' names."""
    out, pools = {}, []
    for i in range(POOLS):
        for name in names:
            (one, pool, tris), (three, _, _) = (instructions(exe, i, name, n) for n in (1, 3))
            out[(i, name)] = (three - one) / 2 / tris
        pools.append(pool)
    return out, pools


def ratio(limit, n):
    return f"{limit / n:.2f}"


after_exe = build_bench(root, root / "target", "pools_pass")
if args.rev:
    with worktree(args.rev) as base:
        # Both sides run today's pass runner (a revision may have an older
        # one, or none: then its Cargo.toml gets the bench too).
        had = (base / "benches" / "pools_pass.rs").exists()
        shutil.copy(root / "benches" / "pools_pass.rs", base / "benches")
        if not had:
            with open(base / "Cargo.toml", "a") as toml:
                toml.write('\n[[bench]]\nname = "pools_pass"\nharness = false\n')
        before, _ = counts(build_bench(base, root / "target" / "pools-ab-base", "pools_pass"))
after, pools = counts(after_exe)

machine = subprocess.run(["uname", "-m"], capture_output=True, text=True).stdout.strip()
if args.rev:
    print(f"Instructions a triangle ({machine}, callgrind): {args.rev} -> working tree.\n")
    print("| pool | " + " | ".join(names) + " |")
    print("|---|" + "---|" * len(names))
    for i, pool in enumerate(pools):
        cells = []
        for name in names:
            b, a = before[(i, name)], after[(i, name)]
            cells.append(f"{b:,.0f} -> {a:,.0f} ({a / b:.2f}x)")
        print(f"| {pool} | " + " | ".join(cells) + " |")
else:
    print(f"Instructions a triangle ({machine}, callgrind), and in brackets the limit's over each"
          " contender's.\n")
    print("| pool | " + " | ".join(names) + " |")
    print("|---|" + "---|" * len(names))
    for i, pool in enumerate(pools):
        limit = after[(i, "limit")]
        cells = [f"{limit:,.0f}"] + [
            f"{after[(i, n)]:,.0f} ({ratio(limit, after[(i, n)])})" for n in names[1:]
        ]
        print(f"| {pool} | " + " | ".join(cells) + " |")
