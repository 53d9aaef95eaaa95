"""The deepest stack a call graph allows: each function's frame plus the
deepest of its callees', along the worst path. The footprint section uses
it on objects (footprint.py) and on linked programs (board_footprint.py)."""
from __future__ import annotations

from pathlib import Path


class StackBoundError(Exception):
    pass


def su_frames(su: Path) -> dict[str, tuple[int, bool]]:
    """A -fstack-usage file: function name -> (frame bytes, bounded)."""
    out = {}
    for line in su.read_text().splitlines():
        where, size, qual = line.split("\t")
        out[where.rsplit(":", 1)[1]] = (int(size), "dynamic" not in qual or "bounded" in qual)
    return out


def deepest_paths(funcs: dict, entries: list[tuple[str, str]]) -> dict[str, dict]:
    """The deepest stack from each entry: funcs maps (file, name) to {"frame",
    "bounded", "calls": [(file, name)]}; the answer maps an entry's name to
    its bytes and the path that takes them. Recursion, or a frame of
    unbounded size, has no bound: StackBoundError."""
    memo: dict = {}
    stack: list = []

    def depth(key) -> tuple[int, list[str]]:
        if key in memo:
            return memo[key]
        if key in stack:
            cycle = [k[1] for k in stack[stack.index(key):]] + [key[1]]
            raise StackBoundError("recursion, so no stack bound: " + " -> ".join(cycle))
        f = funcs[key]
        if not f["bounded"]:
            raise StackBoundError(f"{key[1]} ({key[0]}) has a frame of unbounded size")
        stack.append(key)
        best = (0, [])
        for callee in f["calls"]:
            d = depth(callee)
            if d[0] > best[0]:
                best = d
        stack.pop()
        memo[key] = (f["frame"] + best[0], [key[1]] + best[1])
        return memo[key]

    out = {}
    for key in entries:
        d, path = depth(key)
        out[key[1]] = {"file": key[0], "bytes": d, "path": path}
    return out
