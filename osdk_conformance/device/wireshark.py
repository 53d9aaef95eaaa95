"""`osdkc wireshark install`: puts the generated Wireshark dissector
(generated/wireshark/osdk.lua, `tools/regen.py`) where Wireshark loads Lua
plugins for the current user, so the kit's captures (`osdkc device
--capture`) open decoded instead of as raw "User 0" bytes.

Wireshark's personal Lua plugin folder is ~/.local/lib/wireshark/plugins on
Linux and macOS (it ignores XDG_CONFIG_HOME for plugins: `tshark -G folders`
says "Personal Lua Plugins") and %APPDATA%\\Wireshark\\plugins on Windows.
"""
from __future__ import annotations

import argparse
import os
import shutil
import sys
from pathlib import Path

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import ROOT

# In a checkout ROOT is the repository; installed, pyproject.toml maps
# generated/wireshark to osdk_conformance._data.generated.wireshark, the same
# path under ROOT.
DISSECTOR = ROOT / "generated" / "wireshark" / "osdk.lua"


def personal_plugin_dir() -> Path:
    """The folder Wireshark loads the current user's Lua plugins from."""
    if sys.platform == "win32" and os.environ.get("APPDATA"):
        return Path(os.environ["APPDATA"]) / "Wireshark" / "plugins"
    return Path.home() / ".local" / "lib" / "wireshark" / "plugins"


def install(directory: Path | None = None, source: Path = DISSECTOR) -> Path:
    """Copies the dissector into `directory` (default: the personal plugin
    folder, created when missing); returns the installed file."""
    target_dir = directory if directory is not None else personal_plugin_dir()
    if not source.is_file():
        raise UsageError(f"the dissector {source} is missing (in a checkout, `make regen` writes it)")
    if target_dir.exists() and not target_dir.is_dir():
        raise UsageError(f"cannot install into {target_dir}: not a directory")
    target = target_dir / source.name
    try:
        target_dir.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, target)
    except OSError as e:
        raise UsageError(f"cannot install into {target_dir}: {e.strerror or e}") from None
    return target


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.add_argument("--dir", type=Path, metavar="DIR",
                    help=f"install into DIR instead of Wireshark's personal Lua plugin folder "
                         f"({personal_plugin_dir()})")


def run_install(args: argparse.Namespace) -> int:
    target = install(args.dir)
    print(f"installed {target}")
    print("Wireshark loads it at start (Analyze > Reload Lua Plugins in a running one); "
          "choose the profile in Preferences > Protocols > OSDK, or tshark -o osdk.profile:a3-fw3.1")
    return 0
