"""Helpers of the A/B scripts (`pools_ab.py`, `pools_callgrind.py`): a
bench executable built from a tree, and a revision checked out in a
temporary git worktree."""
import contextlib
import json
import os
import pathlib
import subprocess
import sys
import tempfile

root = pathlib.Path(__file__).resolve().parent.parent


def build_bench(tree, target_dir, name):
    """The executable of bench `name` built in `tree` into `target_dir`."""
    out = subprocess.run(
        ["cargo", "bench", "--bench", name, "--no-run", "--message-format=json"],
        cwd=tree,
        env={**os.environ, "CARGO_TARGET_DIR": str(target_dir)},
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    for line in out.splitlines():
        msg = json.loads(line)
        if msg.get("reason") == "compiler-artifact" and msg["target"]["name"] == name:
            if msg.get("executable"):
                return msg["executable"]
    sys.exit(f"no {name} executable built")


@contextlib.contextmanager
def worktree(rev):
    """`rev` checked out in a temporary git worktree, removed afterwards."""
    with tempfile.TemporaryDirectory() as tmp:
        tree = pathlib.Path(tmp) / "base"
        subprocess.run(["git", "worktree", "add", "--detach", str(tree), rev],
                       cwd=root, check=True, capture_output=True)
        try:
            yield tree
        finally:
            subprocess.run(["git", "worktree", "remove", "--force", str(tree)],
                           cwd=root, check=True, capture_output=True)
