"""The README's "What is here" tree names the folders the repository has,
and nothing that is not there."""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def tree_block() -> list[str]:
    text = (ROOT / "README.md").read_text()
    block = text.split("## What is here", 1)[1].split("```", 2)[1]
    return block.splitlines()


def tracked_dirs() -> set[str]:
    """Top-level folders of the repository (dot folders are tooling, not product)."""
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                           check=True).stdout.split()
    return {f.split("/")[0] for f in files if "/" in f and not f.startswith(".")}


def test_every_top_level_folder_is_in_the_tree() -> None:
    listed = {m.group(1) for line in tree_block() if (m := re.match(r"([\w.-]+)/", line))}
    assert listed == tracked_dirs(), "README.md 'What is here' and the repository's folders differ"


def test_every_osdk_conformance_layer_is_in_the_tree() -> None:
    block = "\n".join(tree_block()).split("osdk_conformance/", 1)[1]
    listed = set(re.findall(r"\b(\w+)/", block.split("\nfuzz/", 1)[0]))
    packages = {p.name for p in (ROOT / "osdk_conformance").iterdir() if (p / "__init__.py").exists()}
    assert packages <= listed, f"not in the README tree: {sorted(packages - listed)}"


def test_every_path_the_tree_names_exists() -> None:
    # `name/` or `name.ext` at the start of an indented entry, under its top-level folder
    top = None
    missing = []
    for line in tree_block():
        if m := re.match(r"([\w.-]+)/", line):
            top = m.group(1)
        elif top and (m := re.match(r"  ([\w.*<>-]+/?)", line)):
            name = m.group(1)
            if "*" in name or "<" in name:
                continue
            for part in name.split():
                if not (ROOT / top / part.rstrip("/")).exists():
                    missing.append(f"{top}/{part}")
    assert missing == []
