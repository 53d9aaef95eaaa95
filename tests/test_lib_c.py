"""The C library (generated/c, issue 17): the examples of examples/c built
against it with its own Makefile, the generated encoders against the
reference encoder on edge values, the build without stdio, and the
footprint bench section on x86-64.

The programs are built by Makefiles (`make -C examples/c build`, the
testee's `make build`); this file runs them."""
from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from library_examples import receive_expected, receive_stream, send_expected
from osdk_conformance import api
from osdk_conformance.reference import codec

ROOT = Path(__file__).resolve().parents[1]
LIB = ROOT / "generated" / "c"
EXAMPLES = ROOT / "examples" / "c"
TESTEE_DIR = ROOT / "conformance" / "testees" / "c"
TESTEE = TESTEE_DIR / "build" / "osdk-c-testee"
PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None or shutil.which("make") is None,
                                reason="needs gcc and make")


@pytest.fixture(scope="module")
def built():
    for d in (EXAMPLES, TESTEE_DIR):
        r = subprocess.run(["make", "-s", "-C", str(d), "build"], capture_output=True, text=True)
        assert r.returncode == 0, r.stdout + r.stderr
    return EXAMPLES / "build"


@pytest.mark.parametrize("profile", PROFILES)
def test_receive_example(built, profile):
    r = subprocess.run([str(built / "receive"), profile], input=receive_stream(profile), capture_output=True,
                       timeout=30)
    assert r.returncode == 0, r.stderr
    assert r.stdout.decode().splitlines() == receive_expected(profile)


def test_receive_unknown_profile(built):
    r = subprocess.run([str(built / "receive"), "m300"], input=b"", capture_output=True, timeout=30)
    assert r.returncode == 2 and r.stdout == b"" and len(r.stderr.decode().strip().splitlines()) == 1


def test_send_example(built):
    r = subprocess.run([str(built / "send")], capture_output=True, timeout=30)
    assert r.returncode == 0, r.stderr
    assert r.stdout.decode().splitlines() == send_expected()


# ---- the encoders against the reference ------------------------------------------------------

F32_EDGES = (0x7F800001, 0x7FBFFFFF, 0xFFC12345, 0x7FC00000, 0x80000000, 0x00000000, 0x00000001, 0x7F7FFFFF,
             0xFF800000, 0x3F800000)


def _frame_cases():
    # (is_ack, session, seq, cmd_set, cmd_id, value)
    return [
        (False, 0, 0x1234, 1, 3, bytes.fromhex("4b0000803f000000c00000003f0000f041")),
        (False, 31, 0xFFFF, 255, 255, bytes(range(256)) * 3 + bytes(1005 - 768)),  # LEN 1023
        (False, 31, 0xFFFF, 255, 255, bytes(1006)),  # LEN 1024: impossible_length
        (False, 0, 0, 0, 0, b""),
        (True, 31, 0xFFFF, None, None, bytes([0xFF]) * 1007),  # LEN 1023
        (True, 1, 5, None, None, bytes(1008)),  # impossible_length
        (True, 0, 9, None, None, b"\x00\x00"),  # bad_session
        (True, 0, 9, None, None, b""),  # bad_session, header-only
        (True, 0, 9, None, None, bytes(1008)),  # impossible_length before bad_session
        (True, 1, 7, None, None, b""),  # the 12-byte header alone
    ]


def _reference(request: dict) -> str:
    a = codec.request_answer(request)
    return a["result"]["hex"] if a["ok"] else a["error"]


def test_encoders_match_reference(built):
    """The testee's encode operations are the generated encoders alone
    (osdk_encode_movement_control_bits, osdk_encode_frame)."""
    requests, expected = [], []
    for i, bits in enumerate(F32_EDGES):
        others = F32_EDGES[(i + 1) % len(F32_EDGES)], F32_EDGES[(i + 3) % len(F32_EDGES)], F32_EDGES[(i + 5) % len(F32_EDGES)]
        mode = (0, 0x4B, 0xFF)[i % 3]
        fs = (bits, *others)
        requests.append({"op": "encode_movement_control", "id": f"m{i}", "mode": mode,
                         **{k: {"f32": f"0x{b:08x}"} for k, b in zip(("x", "y", "z", "yaw"), fs)}})
        expected.append(api.encode_movement_control(mode, *map(api.F32, fs)).hex())
        assert expected[-1] == _reference(requests[-1])
    for i, (is_ack, session, seq, cmd_set, cmd_id, value) in enumerate(_frame_cases()):
        req = {"op": "encode_frame", "id": f"f{i}", "is_ack": is_ack, "session": session, "seq": seq,
               "value": value.hex()}
        if not is_ack:
            req.update(cmd_set=cmd_set, cmd_id=cmd_id)
        requests.append(req)
        expected.append(_reference(req))
    r = subprocess.run([str(TESTEE)], input="".join(json.dumps(q) + "\n" for q in requests), capture_output=True,
                       text=True, timeout=30)
    answers = [json.loads(ln) for ln in r.stdout.splitlines()]
    got = [a["result"]["hex"] if a["ok"] else a["error"] for a in answers]
    assert got == expected
    assert len(bytes.fromhex(got[len(F32_EDGES) + 1])) == 1023
    assert got[len(F32_EDGES) + 2:len(F32_EDGES) + 9:3] == ["impossible_length"] * 3  # cases 2, 5, 8
    assert got[len(F32_EDGES) + 6:len(F32_EDGES) + 8] == ["bad_session"] * 2


def test_encode_unit_tests():
    """Statuses the bytes cannot show (buffer too small, bad arguments), plain and under ASan/UBSan."""
    r = subprocess.run(["make", "-s", "-C", str(TESTEE_DIR), "build/test_encode", "build/test_encode-asan"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    for exe in ("test_encode", "test_encode-asan"):
        r = subprocess.run([str(TESTEE_DIR / "build" / exe)], capture_output=True, text=True, timeout=30)
        assert r.returncode == 0, r.stdout + r.stderr


# ---- the build without stdio ------------------------------------------------------------------

def _poisoned(tmp_path: Path) -> Path:
    """A directory whose stdio.h stops any compilation that includes it
    (an -I directory is searched before the system's for <stdio.h>)."""
    d = tmp_path / "no-stdio"
    d.mkdir()
    (d / "stdio.h").write_text("#error <stdio.h> included in a build without stdio\n")
    return d


def test_no_stdio_build(tmp_path):
    info = json.loads((LIB / "features.json").read_text())
    poison = _poisoned(tmp_path)
    build = tmp_path / "lib"
    r = subprocess.run(["make", "-s", "-C", str(LIB), "OSDK_NO_STDIO=1", f"BUILD={build}", f"CPPFLAGS=-I{poison}",
                        "CFLAGS=-O0 -Wall -Wextra -Werror -pedantic"], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    members = subprocess.run(["ar", "t", str(build / "libosdk.a")], capture_output=True, text=True).stdout.split()
    assert sorted(members) == sorted(f[:-2] + ".o" for f in info["files"] if f not in info["stdio"])
    assert info["stdio"] and not set(f[:-2] + ".o" for f in info["stdio"]) & set(members)
    # the poison works: a file of the stdio set does not compile with it
    bad = subprocess.run(["gcc", "-fsyntax-only", f"-I{poison}", f"-I{LIB}", str(LIB / info["stdio"][0])],
                         capture_output=True, text=True)
    assert bad.returncode != 0 and "without stdio" in bad.stderr


@pytest.mark.skipif(shutil.which("cmake") is None, reason="needs cmake")
def test_cmake_build_no_stdio(tmp_path):
    build = tmp_path / "cmake"
    poison = _poisoned(tmp_path)
    r = subprocess.run(["cmake", "-S", str(LIB), "-B", str(build), "-DOSDK_NO_STDIO=ON",
                        f"-DCMAKE_C_FLAGS=-O0 -I{poison}"], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    r = subprocess.run(["cmake", "--build", str(build), "-j2"], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert (build / "libosdk.a").exists()


def test_features_list_every_file():
    info = json.loads((LIB / "features.json").read_text())
    assert sorted(info["files"]) == sorted(p.name for p in LIB.glob("*.c"))
    by_name = {f["feature"]: f for f in info["features"]}
    assert by_name["encoders"]["libc"] == [] and "osdk_crc.c" in by_name["encoders"]["files"]
    assert not set(by_name["deframer (receiver)"]["files"]) & set(info["stdio"])


@pytest.mark.slow
def test_the_kept_file_features_are_what_the_objects_say():
    """libgen keeps each file's dependencies under .cache/ by the hash of what
    they follow from; measured again from fresh objects, they are the same."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("libgen_c", ROOT / "tools" / "libgen" / "c.py")
    libgen_c = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(libgen_c)
    assert libgen_c.features(LIB) == libgen_c._features_from_objects(LIB)


# ---- the footprint bench section (x86-64 only: fast, and gcc is always there) -----------------

def test_footprint_x86_64(tmp_path):
    from osdk_conformance.bench import footprint
    fp = footprint.measure(("x86-64",), board=False)
    assert fp["ok"], fp
    t = fp["targets"]["x86-64"]
    features = {f["feature"]: f for f in t["features"]}
    assert all(f["text"] > 0 and f["bss"] == 0 for f in features.values())
    assert t["library"]["text"] == sum(s["text"] for s in t["files"].values()) > t["library_no_stdio"]["text"]
    assert features["encoders"]["text"] == t["files"]["osdk_encode.c"]["text"] + t["files"]["osdk_crc.c"]["text"]
    stack = t["stack"]
    assert stack["osdk_frame_decode"]["bytes"] > stack["osdk_frame_parse"]["bytes"] > 0
    assert stack["osdk_frame_decode"]["path"][:2] == ["osdk_frame_decode", "osdk_frame_parse"]
    assert "osdk_crc16" in stack["osdk_encode_frame"]["path"] or "osdk_crc32" in stack["osdk_encode_frame"]["path"]
    assert "next_event" in stack["osdk_deframer_feed"]["path"]  # a static function, through its section's relocation
    # the block replaces only itself
    doc = tmp_path / "PERF.md"
    doc.write_text(f"before\n{footprint.BEGIN}\nold\n{footprint.END}\nafter\n")
    footprint.write_markdown(doc, footprint.markdown(fp, "osdkc bench --only footprint"))
    text = doc.read_text()
    assert text.startswith("before\n") and text.endswith("after\n") and "old" not in text
    assert "| `osdk_encode_frame` | `osdk_encode.c` |" in text


def test_footprint_fails_on_recursion():
    from osdk_conformance.bench import stack_depth
    funcs = {("a.c", "f"): {"frame": 16, "bounded": True, "calls": [("a.c", "g")]},
             ("a.c", "g"): {"frame": 8, "bounded": True, "calls": [("a.c", "f")]}}
    with pytest.raises(stack_depth.StackBoundError, match="recursion.*f -> g -> f"):
        stack_depth.deepest_paths(funcs, [("a.c", "f")])
    funcs = {("a.c", "f"): {"frame": 16, "bounded": False, "calls": []}}
    with pytest.raises(stack_depth.StackBoundError, match="unbounded"):
        stack_depth.deepest_paths(funcs, [("a.c", "f")])


def test_footprint_cortex_m4_compiles_every_file_with_only_its_listed_libc():
    # clang-14 comes with the setup (tools/apt-packages.sh); a file needing more than features.json lists fails here
    from osdk_conformance.bench import footprint
    fp = footprint.measure(("cortex-m4",), board=False)
    assert fp["ok"], fp["targets"]["cortex-m4"].get("error")
    assert fp["targets"]["cortex-m4"]["stack"]["osdk_frame_decode"]["bytes"] > 0


def test_the_tiny_libc_lets_the_compiler_call_memmove_but_wants_the_header_for_the_rest(tmp_path):
    # osdk_deframer.c copies with a loop that gcc turns into memmove: listed, never declared
    from osdk_conformance.bench import footprint
    src = tmp_path / "a.c"
    src.write_text("#include <stdint.h>\nvoid f(uint8_t *d, const uint8_t *s) { while (*s) *d++ = *s++; }\n")
    where = footprint._tiny_libc(src, ["memmove"], tmp_path / "libc-a")
    assert list(where.iterdir()) == []
    with pytest.raises(footprint.FootprintError, match="needs size_t strlen.*but does not include string.h"):
        footprint._tiny_libc(src, ["memmove", "strlen"], tmp_path / "libc-b")
    src.write_text("#include <string.h>\nvoid f(char *d) { memmove(d, d + 1, 2); }\n")
    declared = (footprint._tiny_libc(src, ["memmove"], tmp_path / "libc-c") / "string.h").read_text()
    assert "void *memmove(" in declared
