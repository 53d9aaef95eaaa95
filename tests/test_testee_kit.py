"""The C/C++ testee kit (conformance/testee-kit/c): its example conforms
for the one operation it claims, the kit answers what an implementation's
callbacks leave open (capabilities, unsupported operations and profiles,
bad requests, no answer, two answers, an answer that overflows its room),
floats go both ways as their bits, and the header compiles as C++. The
bundled C testee is built on the kit: `osdkc run --impl c` (test_runner,
test_languages) is the proof on every golden vector."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
KIT = ROOT / "conformance" / "testee-kit" / "c"
GEN = ROOT / "generated" / "c"

# Callbacks that misbehave on purpose, one per thing the kit must catch.
PROBE = r"""
#include <string.h>
#include "okit.h"

static void no_answer(okit_request *req) { (void)req; }

static void two_answers(okit_request *req)
{
    okit_error(req, "undefined_mode", "first");
    okit_error(req, "out_of_range", "second");
}

static void too_long(okit_request *req)
{
    osdk_json_t *w = okit_result(req, 16);
    if (w) osdk_json_string(w, "a result far longer than the sixteen bytes of room it asked for");
}

static void floats(okit_request *req)
{
    uint32_t bits;
    int64_t n;
    osdk_json_t *w;
    if (!okit_f32(req, "x", &bits) || !okit_int(req, "n", 0, 9, &n)) return;
    if (!(w = okit_result(req, 256))) return;
    osdk_json_begin_object(w);
    osdk_json_key(w, "x");
    osdk_json_f32(w, bits);
    osdk_json_key(w, "n");
    osdk_json_int(w, n);
    osdk_json_key(w, "profile");
    osdk_json_int(w, okit_profile(req));
    osdk_json_end_object(w);
}

int main(int argc, char **argv)
{
    static const char *const profiles[] = {"m100-fw3.1", "a3-fw3.1", NULL};
    okit_testee t;
    memset(&t, 0, sizeof t);
    t.name = "probe";
    t.profiles = profiles;
    t.decode_frame = no_answer;
    t.classify_control_mode = two_answers;
    t.decode_payload = too_long;
    t.check_movement_control = floats;
    return okit_main(&t, argc, argv);
}
"""


@pytest.fixture(scope="module")
def probe(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("kit")
    (out / "probe.c").write_text(PROBE)
    exe = out / "probe"
    subprocess.run(["gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", f"-I{KIT}", f"-I{GEN}",
                    "-o", str(exe), str(out / "probe.c"), str(KIT / "okit.c"), str(KIT / "jsonread.c"),
                    str(GEN / "osdk_json.c")], check=True, capture_output=True, text=True)
    return exe


def ask(exe: Path, *lines: str) -> tuple[list[dict], str]:
    done = subprocess.run([str(exe)], input="\n".join(lines) + "\n", capture_output=True, text=True, timeout=30)
    assert done.returncode == 0, done.stderr
    return [json.loads(line) for line in done.stdout.splitlines()], done.stderr


def test_capabilities_list_the_operations_with_a_callback(probe):
    [caps], _ = ask(probe, '{"op": "capabilities"}')
    assert caps == {"ok": True, "result": {"name": "probe", "profiles": ["m100-fw3.1", "a3-fw3.1"], "operations": [
        "decode_frame", "decode_payload", "classify_control_mode", "check_movement_control"]}}


def test_the_kit_answers_what_the_callbacks_leave_open(probe):
    answers, err = ask(
        probe,
        '{"op": "encode_frame", "is_ack": false}',            # no callback
        '{"op": "decode_frame", "profile": "m100-fw2.3"}',    # a profile it does not list
        '{"op": "decode_frame"}',                              # no profile at all
        '{"op": "decode_frame", "profile": "a3-fw3.1"}',      # the callback answers nothing
        '{"op": "classify_control_mode", "profile": "a3-fw3.1", "byte": 1}',   # it answers twice
        '{"op": "decode_payload", "profile": "a3-fw3.1"}',    # its answer overflows its room
        "   ",                                                 # blank: no answer
        "not json",
        '["op"]',
        '{"op": "check_movement_control", "profile": "a3-fw3.1", "n": 1}',
        '{"op": "check_movement_control", "profile": "a3-fw3.1", "x": {"f32": "0x1"}, "n": 10}',
        '{"op": "check_movement_control", "profile": "a3-fw3.1", "x": 1.5, "n": 1}',
    )
    assert answers[0] == answers[1] == answers[2] == {"ok": False, "unsupported": True}
    assert answers[3] == {"ok": False, "error": "internal_error",
                          "detail": "the implementation gave no answer to decode_frame"}
    assert answers[4] == {"ok": False, "error": "undefined_mode", "detail": "first"}
    assert "a second answer to one classify_control_mode request was dropped" in err
    assert answers[5] == {"ok": False, "error": "internal_error", "detail": "the answer does not fit its room"}
    assert [a["error"] for a in answers[6:]] == ["bad_request"] * 5
    assert answers[6]["detail"].startswith("not JSON")
    assert answers[8]["detail"] == "missing argument 'x'"
    assert answers[9]["detail"] == "argument 'n' is out of range"
    assert answers[10]["detail"] == "argument 'x' has the wrong type"


@pytest.mark.parametrize("bits, value", [("0x80000000", -0.0), ("0x7f800001", "NaN"), ("0xff800000", "-Infinity"),
                                         ("0x00000001", 1.40129846e-45), ("0x3fc00000", 1.5)])
def test_floats_go_through_as_their_bits(probe, bits, value):
    [a], _ = ask(probe, json.dumps({"op": "check_movement_control", "profile": "m100-fw3.1", "x": {"f32": bits},
                                    "n": 3}))
    assert a["ok"] and a["result"]["x"]["f32"] == bits and a["result"]["n"] == 3 and a["result"]["profile"] == 0
    got = a["result"]["x"]["value"]
    assert got == value and (str(got) == str(value))   # -0.0 stays -0.0


def test_arguments_without_a_bench_mode_are_a_usage_error(probe):
    done = subprocess.run([str(probe), "--bench", "x"], capture_output=True, text=True, timeout=30)
    assert done.returncode == 2 and "no arguments expected" in done.stderr


@pytest.mark.slow
def test_the_example_conforms_for_what_it_claims():
    subprocess.run(["make", "-s", "-C", str(KIT), "example"], check=True, capture_output=True, text=True)
    done = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "run", "--testee",
                           str(KIT / "build" / "encode-only")], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr
    assert "CONFORMS for encode_movement_control: 287 of" in done.stdout


def test_the_headers_compile_as_cxx():
    done = subprocess.run(["make", "-s", "-C", str(KIT), "cxx-check"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
