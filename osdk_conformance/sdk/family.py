"""What `osdkc sdk build` needs to know about one family of DJI Onboard-SDK
releases: how to recognise a checkout of it, which of its own source files
make the frame layer, the broadcast unpacker and the frame encoder, and
which adapter of ours (conformance/sdk_testee/<family>/) turns them into a
testee of conformance/PROTOCOL.md.

A family module (osdk_conformance/sdk/families/<name>.py) has one function,
`detect(root) -> Recipe | None`: None when the tree is not of that family;
a UsageError naming the missing file or the unsupported version when it is
of that family but cannot be built.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path


@dataclass(frozen=True)
class Recipe:
    family: str                       # "core" (2.3, 3.1.x, 3.2.x: CoreAPI) or "protocol" (3.3 to 3.9: OpenProtocol)
    version: str                      # the release, as the tree says it ("3.1.9")
    profiles: tuple[str, ...]         # the wire profiles this release's broadcast unpacker speaks
    operations: tuple[str, ...]       # the PROTOCOL.md operations the adapter claims: only what the SDK performs
    sdk_sources: tuple[Path, ...]     # the SDK's own .cpp/.c files, compiled unchanged
    includes: tuple[Path, ...]        # the SDK's include directories
    adapter_sources: tuple[Path, ...]  # ours: the adapter and the stubs of what the protocol does not need
    defines: tuple[str, ...] = ()     # what the adapter must know about the release (NAME or NAME=VALUE)
    cxx_std: str = "c++11"
    # error class -> how the adapter derives it from what the SDK did (the
    # report shows these: where the SDK rejects silently, the class is ours)
    derivations: dict[str, str] = field(default_factory=dict)
