"""Which DJI Onboard-SDK release a tree is, and what its recipe claims
(osdk_conformance/sdk/families/), without a checkout: the trees here are
empty files at the paths the releases have, with the few lines of text the
detection reads. The builds themselves are tested with OSDK_SRC
(tests/test_sdk_build.py)."""
from __future__ import annotations

from pathlib import Path

import pytest

from osdk_conformance.core.errors import UsageError
from osdk_conformance.sdk import testee_build
from osdk_conformance.sdk.families import core, protocol

OPERATIONS = {"decode_stream", "decode_frame", "decode_payload", "classify_control_mode",
              "check_movement_control", "encode_movement_control", "encode_frame"}


def tree(root: Path, files: dict[str, str]) -> Path:
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    return root


def core_tree(root: Path, base: str, **text: str) -> Path:
    files = {f"{base}/inc/DJI_API.h": "", **{f"{base}/src/{n}": "" for n in core.NEEDED}}
    files.update({f"{base}/{rel}": t for rel, t in text.items()})
    return tree(root, files)


def protocol_tree(root: Path, heading: str, *, base: bool = True, select: bool = True) -> Path:
    sources = protocol.SDK_SOURCES + protocol.ADAPTER_HEADERS if base else \
        protocol.SDK_SOURCES_33 + protocol.ADAPTER_HEADERS_33
    files = {f"osdk-core/{rel}": "" for rel in sources}
    files["osdk-core/hal/inc/dji_log.hpp"] = "void title(int level, const char* prefix);\n"
    if base:
        files["osdk-core/platform/linux/inc/linux_serial_device.hpp"] = "#include <sys/select.h>\n" if select else ""
    files["README.md"] = heading
    return tree(root, files)


def check_recipe(recipe) -> None:
    assert set(recipe.operations) <= OPERATIONS and recipe.profiles
    assert all(p.is_file() for p in recipe.adapter_sources), recipe.adapter_sources
    assert recipe.derivations and all(isinstance(v, str) and v for v in recipe.derivations.values())


@pytest.mark.parametrize("base, text, version, profiles", [
    ("lib", {}, "2.3", ("m100-fw2.3",)),
    ("lib", {"inc/DJICommonType.h": "", "src/DJI_Link.cpp": "void notifyCaller();"}, "3.1.8", core.DEFAULT_PROFILES),
    ("lib", {"inc/DJICommonType.h": "", "src/DJI_Link.cpp": ""}, "3.1.7", core.DEFAULT_PROFILES),
    ("osdk-core", {"inc/DJI_Version.h": ""}, "3.1.9", core.DEFAULT_PROFILES),
    ("osdk-core", {"inc/DJI_Version.h": "versionA3_32"}, "3.2.0", core.DEFAULT_PROFILES),
    ("osdk-core", {"inc/DJI_Type.h": "uint32_t fwVersion;"}, "3.2.2", core.DEFAULT_PROFILES),
])
def test_the_core_family_tells_its_releases_by_their_code(tmp_path, base, text, version, profiles) -> None:
    recipe = core.detect(core_tree(tmp_path, base, **text))
    assert (recipe.family, recipe.version, recipe.profiles) == ("core", version, profiles)
    assert not any(p.name == "DJI_Codec.cpp" for p in recipe.sdk_sources)   # the adapter includes it
    check_recipe(recipe)
    assert testee_build.detect(tmp_path).version == version


def test_a_core_tree_without_a_file_it_needs_names_it(tmp_path) -> None:
    root = core_tree(tmp_path, "osdk-core")
    (root / "osdk-core/src/DJI_Memory.cpp").unlink()
    with pytest.raises(UsageError, match="missing osdk-core/src/DJI_Memory.cpp"):
        core.detect(root)


@pytest.mark.parametrize("heading, version", [
    ("# DJI Onboard SDK (OSDK) 3.9\n\nOSDK 3.9.0 was released on ...\n", "3.9.0"),
    ("# DJI Onboard SDK (OSDK) 3.6\n", "3.6"),
])
def test_the_protocol_family_reads_the_release_from_the_readme(tmp_path, heading, version) -> None:
    recipe = protocol.detect(protocol_tree(tmp_path, heading))
    assert (recipe.family, recipe.version, recipe.profiles) == ("protocol", version, protocol.PROFILES)
    assert f'OKIT_SDK_VERSION="{version}"' in recipe.defines
    assert protocol.SELECT_SHIM not in recipe.includes
    check_recipe(recipe)


def test_a_serial_header_without_select_gets_the_shim(tmp_path) -> None:
    recipe = protocol.detect(protocol_tree(tmp_path, "# DJI Onboard SDK (OSDK) 3.4\n", select=False))
    assert recipe.includes[0] == protocol.SELECT_SHIM and protocol.SELECT_SHIM.is_dir()


def test_3_3_takes_the_single_class_receiver_path(tmp_path) -> None:
    recipe = protocol.detect(protocol_tree(tmp_path, "# DJI Onboard SDK (OSDK) 3.3\n", base=False))
    assert recipe.version == "3.3" and "OKIT_SDK_PROTOCOL_33" in recipe.defines
    assert any(p.name == "stubs33.cpp" for p in recipe.adapter_sources)
    assert recipe.derivations == protocol.DERIVATIONS_33
    check_recipe(recipe)


def test_protocol_trees_that_cannot_be_built_are_named(tmp_path) -> None:
    with pytest.raises(UsageError, match="not in README.md"):
        protocol.detect(protocol_tree(tmp_path / "a", "no heading\n"))
    root = protocol_tree(tmp_path / "b", "# DJI Onboard SDK (OSDK) 3.8\n")
    (root / "osdk-core/protocol/src/dji_protocol_base.cpp").unlink()
    with pytest.raises(UsageError, match="lacks osdk-core/protocol/src/dji_protocol_base.cpp"):
        protocol.detect(root)
    with pytest.raises(UsageError, match="Onboard-SDK 4.0 is not supported"):
        protocol.detect(protocol_tree(tmp_path / "c", "# DJI Onboard SDK (OSDK) 4.0\n"))


def test_a_4x_tree_is_refused_as_a_prebuilt_frame_layer(tmp_path) -> None:
    root = tree(tmp_path, {"osdk-core/linker/x86/lib/libdji-linker.a": "", "README.md": "# DJI Onboard SDK (OSDK) 4.0\n"})
    with pytest.raises(UsageError, match="4.x is not supported: its frame layer is the prebuilt library"):
        testee_build.detect(root)


def test_a_tree_of_neither_family_is_none_for_both(tmp_path) -> None:
    assert core.detect(tmp_path) is None and protocol.detect(tmp_path) is None
