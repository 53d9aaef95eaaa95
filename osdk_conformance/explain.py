"""`osdkc explain`: what a control mode byte, an ACK code or a frame means,
read from the spec's tables (spec/rules.yaml through core/rules.py, the .ksy
files through core/ksy.py, the reference decoder), never from a second copy
of them.

    osdkc explain 0x4B                       # the control mode byte, on every profile
    osdkc explain --control-mode 0b01001011 --profile m100-fw2.3
    osdkc explain --ack activation 3         # the code's name, meaning and remedy
    osdkc explain --hex "AA 1A 00 ..." --profile a3-fw3.1   # a frame, field by field

Exit status: 0 explained (an ACK code the spec does not define for the
command is explained as such), 2 bad input.
"""
from __future__ import annotations

import argparse
import functools
import json
import re
import sys
from dataclasses import dataclass
from typing import Any, Iterable, Iterator

from osdk_conformance.core import ksy
from osdk_conformance.core.commands import COMMANDS, command_name
from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.deframe import HEADER_LEN, MAX_LEN, frame_length
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import SPEC
from osdk_conformance.core.rules import Rules, default_rules, errata_ids
from osdk_conformance.reference import codec
from osdk_conformance.reference.decode import parse_hex, profiles_decoding

# A frame is explained in this profile when --profile is not given: only a
# broadcast's layout depends on it, and the output then says so.
DEFAULT_FRAME_PROFILE = "a3-fw3.1"
_ERRATUM = re.compile(r"\bE\d\d\b")


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.description = __doc__.split("\n\n")[0]
    ap.epilog = ("exit status: 0 explained (also an ACK code the spec does not define for the command: "
                 "the output says so); 2 bad input, said in one line on standard error")
    ap.add_argument("byte", nargs="?", help="a control mode byte: 0x4B, 75 or 0b01001011")
    what = ap.add_mutually_exclusive_group()
    what.add_argument("--control-mode", metavar="BYTE", help="the control mode byte (as the positional argument)")
    what.add_argument("--ack", nargs=2, metavar=("COMMAND", "CODE"),
                      help="an ACK code of a command (version_query, activation, set_frequency, "
                           "control_authority, or SET,ID like 0x00,0x01), in decimal or hex")
    what.add_argument("--hex", metavar="FRAME", help="one frame as hex (spaces and colons allowed)")
    ap.add_argument("--profile", choices=profiles,
                    help="the wire profile (default: every profile for a mode byte; "
                         f"{DEFAULT_FRAME_PROFILE} for --hex, which only a broadcast's layout depends on)")
    ap.add_argument("--json", action="store_true", help="the explanation as one JSON object")


def run_explain(args: argparse.Namespace) -> int:
    chosen = [x for x in (args.byte, args.control_mode, args.ack, args.hex) if x is not None]
    if len(chosen) != 1:
        raise UsageError("give one thing to explain: a control mode byte, --ack COMMAND CODE or --hex FRAME")
    if args.ack is not None:
        out, text = explain_ack(*args.ack, profile=args.profile), _ack_text
    elif args.hex is not None:
        out, text = explain_frame(_hex(args.hex), args.profile), _frame_text
    else:
        byte = _number(args.byte if args.byte is not None else args.control_mode, "control mode byte", 0xFF)
        out, text = explain_mode(byte, args.profile), _mode_text
    if args.json:
        sys.stdout.write(json.dumps(out, indent=2) + "\n")
    else:
        sys.stdout.write(text(out))
    return 0


# ---- errata ------------------------------------------------------------------------------


@functools.cache
def _errata_titles() -> dict[str, str]:
    text = (SPEC / "ERRATA.md").read_text(encoding="utf-8")
    return dict(re.findall(r"^## (E\d+): (.*)$", text, re.M))


@functools.cache
def _known_errata() -> frozenset[str]:
    return frozenset(errata_ids())


def _errata(texts: Iterable[str]) -> list[dict[str, str]]:
    """The ERRATA.md entries the rules' `source:` strings (and reasons) name, with their titles."""
    known = _known_errata()
    ids = sorted({e for t in texts for e in _ERRATUM.findall(t or "")} & known)
    return [{"id": e, "title": _errata_titles().get(e, "")} for e in ids]


# ---- the control mode byte -------------------------------------------------------------


def explain_mode(byte: int, profile: str | None = None) -> dict[str, Any]:
    """Fields, frame, and per profile the classification of rules.classify_control_mode with the
    input ranges of rules.input_ranges (the functions the reference testee answers with)."""
    rules = default_rules()
    views = {p: rules.classify_control_mode(byte, p) for p in ([profile] if profile else rules.profile_names)}
    first = next(iter(views.values()))
    return {"byte": byte, "hex": f"0x{byte:02X}", "binary": f"0b{byte:08b}",
            "fields": _mode_fields(rules, first["raw"], first["fields"]),
            "frame": _frame_meaning(rules, first["fields"]),
            "profiles": {p: _mode_on_profile(rules, c) for p, c in views.items()},
            "errata": _errata(_mode_sources(rules, views))}


def _mode_fields(rules: Rules, raw: dict[str, int], names: dict[str, str | None]) -> list[dict[str, Any]]:
    out = []
    for f in rules.data["control_mode"]["fields"]:
        value = raw[f["name"]]
        hi = f["lsb"] + f["width"] - 1
        row: dict[str, Any] = {"field": f["name"], "bits": f"{hi}:{f['lsb']}" if f["width"] > 1 else str(hi),
                               "value": value, "name": names[f["name"]]}
        undefined = next((u for u in f["undefined"] if u["value"] == value), None)
        if undefined:
            row.update(undefined=undefined["classification"], reason=undefined["reason"])
        out.append(row)
    return out


def _frame_meaning(rules: Rules, names: dict[str, str | None]) -> str:
    frame = names["horizontal_frame"]  # the field's value name in rules.yaml: ground or body
    text = f"horizontal setpoints in the {frame} frame" if frame else "no defined horizontal frame (bits 2:1)"
    forced = rules.data["control_mode"]["yaw_angle_forces_ground_frame"]
    if names["yaw_logic"] == "yaw_ang" and forced["value"]:
        text += "; " + forced["meaning"]
    return text


def _mode_on_profile(rules: Rules, c: dict[str, Any]) -> dict[str, Any]:
    ranges = rules.input_ranges(c["byte"], c["profile"])
    return {"classification": c["classification"], "combination": c["combination"], "bit0": c["bit0"],
            "reasons": c["reasons"], "preconditions": c["preconditions"],
            "ranges": _ranges(rules, ranges) if ranges else None}


def _ranges(rules: Rules, ranges: dict[str, dict]) -> dict[str, dict]:
    """Each part's axes (rules.yaml control_modes.axes) with its range, unit and source."""
    axes = rules.data["control_modes"]["axes"]
    keep = ("min", "max", "unit", "max_ref", "note", "source")
    return {part: {"axes": axes[part], **{k: r[k] for k in keep if k in r}}
            for part, r in ((p, ranges[p]) for p in ("horizontal", "vertical", "yaw"))}


def _mode_sources(rules: Rules, views: dict[str, dict]) -> list[str]:
    """The `source:` of every rule that decided something about the byte, and the reasons:
    what the errata list is read from."""
    cm = rules.data["control_mode"]
    c0 = next(iter(views.values()))
    texts = [cm["source"]]
    for f in cm["fields"]:
        texts += [u["source"] for u in f["undefined"] if u["value"] == c0["raw"][f["name"]]]
    if c0["fields"]["yaw_logic"] == "yaw_ang":
        texts.append(cm["yaw_angle_forces_ground_frame"]["source"])
    for p, c in views.items():
        texts += c["reasons"] + [cm["bit0_by_profile"][p]["source"]]
        texts += [pre["source"] for pre in cm["preconditions"] if pre["id"] in c["preconditions"]]
        if c["combination"]:
            combo = rules.combination(c["combination"])
            texts += [combo["source"]] + [r["source"] for r in combo["ranges"][p].values()]
    return texts


def _mode_text(out: dict) -> str:
    lines = [f"control mode byte {out['hex']} = {out['binary']}", ""]
    for f in out["fields"]:
        what = f["name"] or f"undefined ({f['undefined']}: {f['reason']})"
        lines.append(f"  bit {f['bits']:4} {f['field']:18} {f['value']}  {what}")
    lines += ["", f"  {out['frame']}", ""]
    for p, c in out["profiles"].items():
        lines += _profile_lines(p, c)
    if out["errata"]:
        lines += ["", "errata:"] + [f"  {e['id']}  {e['title']}" for e in out["errata"]]
    return "\n".join(lines) + "\n"


def _profile_lines(p: str, c: dict) -> list[str]:
    combo = f", combination {c['combination']} of the seed's table" if c["combination"] else ""
    lines = [f"{p}: {c['classification'].upper()}{combo}; bit 0 is {c['bit0']['meaning']} ({c['bit0']['name']})"]
    lines += [f"    {r}" for r in c["reasons"]]
    for part, r in (c["ranges"] or {}).items():
        top = _num(r["max"]) if r.get("max") is not None else r.get("max_ref", "no limit")
        note = f" ({r['note']})" if r.get("note") else ""
        lines.append(f"    {part:10} {', '.join(r['axes']):24} {_num(r.get('min'))} to {top} {r['unit']}{note}")
    if c["preconditions"]:
        lines.append(f"    preconditions: {', '.join(c['preconditions'])}")
    return lines


def _num(v: float | None) -> str:
    return "no limit" if v is None else f"{v:g}"


# ---- ACK codes ---------------------------------------------------------------------------


@functools.cache
def ack_enums() -> dict[str, str]:
    """Command name -> the enum (spec/rules.yaml `enums`) of its ACK's code, as osdk_payload.ksy
    types it: the ACK cases (key 0x1SSII) of the `body` switch whose type has an `ack_code`
    field with an `enum:`. lost_control's ACK code has none: the spec names no codes for it."""
    index = ksy.load()
    body = next(f for f in index.files["osdk_payload"]["seq"] if f["id"] == "body")
    out = {}
    for key, ref in body["type"]["cases"].items():
        if not isinstance(key, int) or not key & 0x10000:
            continue
        type_name = ref.partition("(")[0]  # "version_ack_value(profile)": the type, without its argument
        code = index.types[("osdk_payload", (type_name,))].fields.get("ack_code")
        if code is not None and code.enum:
            out[command_name(key >> 8 & 0xFF, key & 0xFF)] = code.enum
    return out


def explain_ack(command: str, code_text: str, profile: str | None = None) -> dict[str, Any]:
    name = _command(command)
    enums = ack_enums()
    if name not in enums:
        raise UsageError(f"{command}: the spec gives no ACK codes for {name} (commands with codes: "
                         f"{', '.join(enums)})")
    rules = default_rules()
    block = rules.data["enums"][enums[name]]
    code = _number(code_text, "ACK code", (1 << int(block["storage"][1:])) - 1)
    row = next((v for v in block["values"] if v["value"] == code), None)
    out: dict[str, Any] = {"command": name, "enum": enums[name], "code": code, "hex": f"0x{code:04X}",
                           "source": block["source"]}
    if row is None:
        out.update(name=None, meaning=f"code {code} (0x{code:04X}) is not defined by the spec for {name}",
                   defined=[{"value": v["value"], "name": v["name"]} for v in block["values"]])
    else:
        out.update(name=row["name"], meaning=row.get("meaning", ""), remedy=row.get("remedy", ""),
                   remedy_source=row.get("remedy_source", ""))
    if name == "activation":
        # The request carries the SDK version word, and a wrong one is the refusal users meet
        # most (code 8): the value each profile's firmware expects (rules.yaml profiles) saves a look-up.
        out["sdk_versions"] = {p: f"0x{rules.profile(p).sdk_version:08X}"
                               for p in ([profile] if profile else rules.profile_names)}
    out["errata"] = _errata([block["source"], (row or {}).get("remedy_source", "")])
    return out


def _command(text: str) -> str:
    if text in COMMANDS.values():
        return text
    m = re.fullmatch(r"\s*(0x[0-9a-fA-F]+|\d+)\s*,\s*(0x[0-9a-fA-F]+|\d+)\s*", text)
    if m and (int(m.group(1), 0), int(m.group(2), 0)) in COMMANDS:
        return COMMANDS[(int(m.group(1), 0), int(m.group(2), 0))]
    raise UsageError(f"unknown command {text!r} (known: {', '.join(COMMANDS.values())}, or SET,ID like 0x00,0x01)")


def _ack_text(out: dict) -> str:
    head = f"{out['command']} ACK {out['hex']} ({out['code']})"
    if out["name"] is None:
        defined = ", ".join(f"{d['value']} {d['name']}" for d in out["defined"])
        lines = [f"{head}: {out['meaning']}", f"  defined: {defined}"]
    else:
        lines = [f"{head}: {out['name']}", f"  meaning: {out['meaning']}", f"  remedy:  {out['remedy']}",
                 f"  source:  {out['remedy_source']}"]
    if "sdk_versions" in out:
        lines.append("  sdk_version by profile: " + ", ".join(f"{p} {v}" for p, v in out["sdk_versions"].items()))
    if out["errata"]:
        lines.append("  errata:  " + "; ".join(f"{e['id']} {e['title']}" for e in out["errata"]))
    return "\n".join(lines) + "\n"


# ---- a frame -----------------------------------------------------------------------------


@dataclass(frozen=True)
class HeaderField:
    id: str        # the ksy seq id: sof, len, ver, session, is_ack, ...
    start: int     # first bit, counting from bit 0 of byte 0 (the ksy is bit-endian le)
    width: int     # bits
    enum: str | None
    doc: str


def _bits(f: dict) -> int:
    if "contents" in f:
        return 8 * len(f["contents"])
    m = re.fullmatch(r"b(\d+)|[us](\d)", f["type"])
    if not m:
        raise ValueError(f"osdk_frame.ksy header field {f['id']}: type {f['type']} is not a bit field or integer")
    return int(m.group(1)) if m.group(1) else 8 * int(m.group(2))


@functools.cache
def header_layout() -> tuple[HeaderField, ...]:
    """The 12-byte header's fields as osdk_frame.ksy lays them out (sof up to crc16). The ksy is
    little-endian in bits and bytes, so each field is a run of bits of the header read as one
    little-endian integer."""
    index = ksy.load()
    out, bit = [], 0
    for f in index.raw_seq(index.types[("osdk_frame", ())]):
        width = _bits(f)
        out.append(HeaderField(f["id"], bit, width, f.get("enum"), " ".join((f.get("doc") or "").split())))
        bit += width
        if f["id"] == "crc16":
            break
    assert bit == HEADER_LEN * 8, "osdk_frame.ksy: the header is not 12 bytes"
    return tuple(out)


def _span(first: int, last: int) -> str:
    return f"byte {first}" if first == last else f"bytes {first}-{last}"


def _where(start: int, width: int) -> str:
    """Where a run of header bits is, for people: whole bytes, or the bits of one byte."""
    first, last = start // 8, (start + width - 1) // 8
    if start % 8 == 0 and width % 8 == 0:
        return _span(first, last)
    if first != last:
        return f"{_span(first, last)}, {width} bits"
    lo = start % 8
    return f"byte {first} bit {lo}" if width == 1 else f"byte {first} bits {lo}-{lo + width - 1}"


def _header_values(raw: bytes) -> dict[str, int]:
    """Each header field the bytes hold whole, by its ksy id."""
    word = int.from_bytes(raw[:HEADER_LEN], "little")
    return {f.id: word >> f.start & ((1 << f.width) - 1) for f in header_layout() if f.start + f.width <= 8 * len(raw)}


def _header_rows(raw: bytes, values: dict[str, int]) -> list[dict[str, Any]]:
    """The header fields the bytes hold whole, with their values and the ksy's doc of each."""
    enums = ksy.load().enums
    rows = []
    for f in header_layout():
        if f.id not in values:
            break
        value = values[f.id]
        row: dict[str, Any] = {"field": f.id.upper(), "where": _where(f.start, f.width), "value": value}
        if f.enum:
            row["name"] = enums[("osdk_frame", f.enum)].get(value)
        if f.id in ("sof", "crc16"):
            row["value"] = f"0x{value:0{f.width // 4}X}"
        if f.id == "crc16":
            row["computed"] = f"0x{crc16(raw[:10]):04X}"  # over bytes 0-9 (rules.yaml crc.crc16.covers)
        row["doc"] = f.doc
        rows.append(row)
    return rows


def _data_rows(raw: bytes, h: dict[str, int]) -> list[dict[str, Any]]:
    """What DATA holds, as far as the bytes hold it whole: command set and id (command frames),
    the value's bytes, the CRC-32 with the one computed."""
    if len(raw) < HEADER_LEN:
        return []
    length = h["len"]
    if length <= HEADER_LEN:
        return []
    end = min(len(raw), length - 4)  # the DATA bytes present
    rows: list[dict[str, Any]] = []
    if h["enc"]:
        rows.append({"field": "DATA", "where": _span(HEADER_LEN, length - 5), "value": raw[HEADER_LEN:end].hex(),
                     "name": "not plain (ENC is not 0): ciphertext as sent, which the CRCs cover"})
    elif h["is_ack"]:
        rows.append({"field": "ACK_VALUE", "where": _span(HEADER_LEN, length - 5), "value": raw[HEADER_LEN:end].hex(),
                     "name": "typed by the command it answers (same session and SEQ, ERRATA E32); "
                             "see osdkc explain --ack"})
    elif end >= HEADER_LEN + 2:
        cmd_set, cmd_id = raw[HEADER_LEN], raw[HEADER_LEN + 1]
        rows += [{"field": "CMD_SET", "where": f"byte {HEADER_LEN}", "value": f"0x{cmd_set:02X}",
                  "name": ksy.load().enums[("osdk_frame", "command_set")].get(cmd_set)},
                 {"field": "CMD_ID", "where": f"byte {HEADER_LEN + 1}", "value": f"0x{cmd_id:02X}",
                  "name": command_name(cmd_set, cmd_id)},
                 {"field": "VALUE", "where": _span(HEADER_LEN + 2, length - 5),
                  "value": raw[HEADER_LEN + 2:end].hex()}]
    if len(raw) >= length:
        rows.append({"field": "CRC32", "where": _span(length - 4, length - 1),
                     "value": f"0x{int.from_bytes(raw[length - 4:length], 'little'):08X}",
                     "computed": f"0x{crc32(raw[:length - 4]):08X}"})
    return rows


def explain_frame(raw: bytes, profile: str | None = None) -> dict[str, Any]:
    """The frame field by field. The verdict is the reference decoder's (codec's decode_frame, the
    operation the golden vectors pin): this explains the spec's decision and takes none of its own."""
    used = profile or DEFAULT_FRAME_PROFILE
    answer = codec.answer("decode_frame", used, {"hex": raw.hex()})
    values = _header_values(raw)
    data = _data_rows(raw, values)
    command = next((r["name"] for r in data if r["field"] == "CMD_ID"), None)
    out: dict[str, Any] = {"bytes": len(raw), "profile": used, "verdict": "valid" if answer["ok"] else "rejected",
                           "fields": _header_rows(raw, values) + data, "command": command,
                           "value": None, "breaks_at": None}
    if answer["ok"]:
        decoded = answer["result"]["frame"].get("data")  # absent (header only), hex (encrypted) or a model
        if isinstance(decoded, dict) and "value" in decoded:
            out["value"] = decoded["value"]["body"]
    else:
        out["breaks_at"] = _breaks_at(raw, answer["error"], answer.get("detail", ""), used, command)
    if profile is None and out["command"] == "broadcast":
        out["note"] = _broadcast_note(raw, out["verdict"])
    return out


def _broadcast_note(raw: bytes, verdict: str) -> str:
    said = f"a broadcast, explained as {DEFAULT_FRAME_PROFILE} (no --profile)"
    if len(raw) < frame_length(raw) or frame_length(raw) < HEADER_LEN + 6:
        return said
    others = profiles_decoding([raw[HEADER_LEN + 2:frame_length(raw) - 4]], DEFAULT_FRAME_PROFILE)
    return f"{said}; its value also decodes as {', '.join(others)}" if others else \
        f"{said}; no other profile decodes its value" + ("" if verdict == "valid" else " either")


# ---- where a frame breaks, and what the receiver does then ------------------------------------------


# Error class -> header field, for the checks of deframe.header_problem and codec.frame_problem.
HEADER_ERROR_FIELD = {"bad_sof": "sof", "bad_crc16": "crc16", "bad_version": "ver", "impossible_length": "len",
                      "bad_crc32": "crc32"}
# Header fields a failed check of the Construct spec names in its path (decode.FIELD_ERRORS' names).
_VALUE_CHECK_FIELDS = ("padding", "enc", "is_ack", "session", "res0", "res1")


def _breaks_at(raw: bytes, error: str, detail: str, profile: str, command: str | None) -> dict[str, Any]:
    # codec.frame_problem is what the receiver itself rejects; anything else is in a frame it took
    receiver_level = codec.frame_problem(raw) is not None
    field = _broken_field(raw, error, detail, receiver_level)
    sources = _frame_rule_sources(field, command)
    if receiver_level:
        sources.append(_receiver_rule()["source"])
    return {"error": error, "field": field.upper(), "detail": detail,
            "receiver": _receiver_does(raw, error, receiver_level, profile), "errata": _errata(sources)}


def _broken_field(raw: bytes, error: str, detail: str, receiver_level: bool) -> str:
    """The ksy id of the first field that is wrong, in the order the receiver checks them
    (rules.yaml frame.receiver.header_checks), then the value's own checks."""
    if error in HEADER_ERROR_FIELD:
        return HEADER_ERROR_FIELD[error]
    if error == "reserved_bits" and receiver_level:
        return "res0" if detail.startswith("RES0") else "res1"
    if error in ("truncated_frame", "length_mismatch") and receiver_level:
        return "len" if len(raw) >= HEADER_LEN else "header"
    named = [f for f in _VALUE_CHECK_FIELDS if re.search(rf"\b(_valid_)?{f}\b", detail)]
    return named[0] if named else "value"


def _receiver_rule() -> dict:
    return default_rules().data["frame"]["receiver"]


# What each action of rules.yaml frame.receiver means for the bytes (core/deframe.py does it).
RECEIVER_ACTIONS = {
    "drop_one_byte": "drops the 0xAA at byte 0 and hunts for the next 0xAA from byte 1 on "
                     "(a frame may start inside these bytes)",
    "rescan_after_sof": "searches again from the byte after the rejected 0xAA, so a frame hidden inside "
                        "this one is still found",
}


def _receiver_does(raw: bytes, error: str, receiver_level: bool, profile: str) -> str:
    rule = _receiver_rule()
    if not receiver_level:
        return ("takes the frame (the checks it makes, header and CRCs, pass) and moves past its LEN bytes; "
                "the spec's own checks (osdk_frame.ksy, osdk_payload.ksy) reject it, so a decoder does")
    if error == "bad_sof":
        return "skips every byte up to the next 0xAA: these bytes are garbage to it"
    if error == "bad_crc32":
        return RECEIVER_ACTIONS[rule["bad_crc32"]]
    if error == "truncated_frame":
        whole, want = ("frame", frame_length(raw)) if len(raw) >= HEADER_LEN else ("header", HEADER_LEN)
        return (f"waits for the other {want - len(raw)} byte(s) of the {whole}; where the input ends first, "
                "the frame is lost and the receiver hunts again from byte 1")
    if error == "length_mismatch":
        return _after_overlong(raw, profile)
    return RECEIVER_ACTIONS[rule["bad_header"]]


def _after_overlong(raw: bytes, profile: str) -> str:
    length = frame_length(raw)
    inner = codec.answer("decode_frame", profile, {"hex": raw[:length].hex()})
    verdict = "a valid frame" if inner["ok"] else f"rejected: {inner['error']}"
    return (f"takes the first {length} bytes (LEN) as one frame ({verdict}) and hunts for the next 0xAA "
            f"in the {len(raw) - length} byte(s) after them")


def _frame_rule_sources(field: str, command: str | None) -> list[str]:
    """The `source:` of the rules.yaml entries about a frame field: what its errata are read from.
    Of a value, only the broadcast's bounds are frame rules (frame.broadcast)."""
    d = default_rules().data
    frame = d["frame"]
    by_field = {
        "sof": [frame["source"]], "ver": [frame["source"]], "header": [frame["source"]],
        "len": [frame["source"], frame["header_only"]["source"]] + [r["source"] for r in frame["impossible_lengths"]["ranges"]],
        "crc16": [d["crc"]["crc16"]["source"]], "crc32": [d["crc"]["crc32"]["source"]],
        "session": [frame["session"]["source"]], "is_ack": [frame["ack_bit"]["source"], frame["session"]["source"]],
        "enc": [frame["enc"]["source"], frame["padding"]["source"]], "padding": [frame["padding"]["source"]],
        "value": [frame["broadcast"]["source"]] if command == "broadcast" else [],
    }
    by_field.update({r["field"]: [r["source"]] for r in frame["reserved_zero"]})
    return by_field.get(field, [])


def _frame_text(out: dict) -> str:
    head = f"{out['bytes']} bytes, {out['profile']}: {out['verdict'].upper()}"
    lines = [head + (f", command {out['command']}" if out["command"] else "")]
    broken = (out["breaks_at"] or {}).get("field")
    width = max((len(f["where"]) for f in out["fields"]), default=0)
    for f in out["fields"]:
        lines.append(_field_line(f, width, f["field"] == broken))
    if out["value"] is not None:
        lines.append("value:")
        leaves = list(_leaves(out["value"]))
        pad = max((len(k) for k, _ in leaves), default=0)
        lines += [f"  {k:{pad}}  {v}" for k, v in leaves]
    if out["breaks_at"]:
        b = out["breaks_at"]
        lines += [f"first wrong field: {b['field']} ({b['error']}: {b['detail']})", f"the receiver {b['receiver']}"]
        if b["errata"]:
            lines.append("errata: " + "; ".join(f"{e['id']} {e['title']}" for e in b["errata"]))
    if out.get("note"):
        lines.append(out["note"])
    return "\n".join(lines) + "\n"


def _field_line(f: dict, width: int, broken: bool) -> str:
    value = str(f["value"])
    if f.get("name"):
        value += f" {f['name']}"
    if "computed" in f and f["computed"] != f["value"]:
        value += f" (computed {f['computed']})"
    return f"  {f['field']:9} {f['where']:{width}}  {value}" + ("   <- first wrong field" if broken else "")


def _leaves(node: Any, path: str = "") -> Iterator[tuple[str, str]]:
    """A decoded value (docs/VALUE-MODEL.md) as (dotted path, text) pairs: an enum as "1 (name)",
    a float as its value and bits."""
    if isinstance(node, dict) and ("f32" in node or "f64" in node):
        bits = "f32" if "f32" in node else "f64"
        yield path, f"{node['value']} ({bits} {node[bits]})"
    elif isinstance(node, dict) and set(node) == {"value", "name"}:
        yield path, f"{node['value']}" + (f" ({node['name']})" if node["name"] is not None else "")
    elif isinstance(node, dict):
        for k, v in node.items():
            yield from _leaves(v, f"{path}.{k}" if path else k)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from _leaves(v, f"{path}[{i}]")
    else:
        yield path, json.dumps(node) if isinstance(node, bool) else str(node)


# ---- input -------------------------------------------------------------------------------


def _number(text: str, what: str, top: int) -> int:
    try:
        n = int(text.replace("_", ""), 0)
    except (ValueError, AttributeError):
        raise UsageError(f"{what} {text!r} is not a number (0x4B, 75, 0b01001011)") from None
    if not 0 <= n <= top:
        raise UsageError(f"{what} {text} is out of range 0..{top}")
    return n


def _hex(text: str) -> bytes:
    # Each group of digits must be whole bytes: "a a" is two typos, not the byte 0xAA.
    for group in re.split(r"[\s:,]+", text.strip()):
        if len(group.removeprefix("0x").removeprefix("0X")) % 2:
            raise UsageError(f"--hex: {group!r} is not whole bytes (two hex digits per byte)")
    data = parse_hex(text)
    if not data:
        raise UsageError("--hex: no bytes given")
    if len(data) > MAX_LEN:
        raise UsageError(f"--hex: {len(data)} bytes; one frame is at most {MAX_LEN} (LEN has 10 bits). "
                         "For a stream of frames use osdkc decode --hex")
    return data
