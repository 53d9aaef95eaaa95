"""`osdkc explain`: what a control mode byte, an ACK code or a frame means,
read from the spec's tables (spec/rules.yaml, the Construct spec, the
reference decoder), never from a second copy of them.

    osdkc explain 0x4B                       # the control mode byte, on every profile
    osdkc explain --control-mode 0b01001011 --profile m100-fw2.3
    osdkc explain --ack activation 3         # the code's name, meaning and remedy
    osdkc explain --hex "AA 1A 00 ..." --profile a3-fw3.1   # a frame, field by field
"""
from __future__ import annotations

import argparse
import json
import re
import sys
from typing import Any

from osdk_conformance.core.commands import COMMANDS
from osdk_conformance.core.crc import crc16
from osdk_conformance.core.deframe import HEADER_LEN, MAX_LEN, header_fields
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.rules import default_rules, errata_ids, profile_names
from osdk_conformance.reference import codec
from osdk_conformance.reference.decode import parse_hex

# the ACK enum of each command that has one (spec/rules.yaml enums, facts §2 command table)
ACK_ENUMS = {"version_query": "version_ack", "activation": "activation_result", "set_frequency": "frequency_ack",
             "control_authority": "control_ack"}
_ERRATUM = re.compile(r"\bE\d\d\b")


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.description = __doc__.split("\n\n")[0]
    ap.add_argument("byte", nargs="?", help="a control mode byte: 0x4B, 75 or 0b01001011")
    what = ap.add_mutually_exclusive_group()
    what.add_argument("--control-mode", metavar="BYTE", help="the control mode byte (as the positional argument)")
    what.add_argument("--ack", nargs=2, metavar=("COMMAND", "CODE"),
                      help=f"an ACK code of a command ({', '.join(ACK_ENUMS)}, or SET,ID like 0x00,0x01)")
    what.add_argument("--hex", metavar="FRAME", help="a frame as hex (spaces allowed)")
    ap.add_argument("--profile", choices=profiles, help="the wire profile (default: every profile for a mode byte; "
                                                        "needed by --hex for a broadcast)")
    ap.add_argument("--json", action="store_true", help="the explanation as JSON")


def run_explain(args: argparse.Namespace) -> int:
    chosen = [x for x in (args.byte, args.control_mode, args.ack, args.hex) if x is not None]
    if len(chosen) != 1:
        raise UsageError("give one thing to explain: a control mode byte, --ack COMMAND CODE or --hex FRAME")
    if args.ack is not None:
        out = explain_ack(*args.ack)
        text = _ack_text
    elif args.hex is not None:
        out = explain_frame(_hex(args.hex), args.profile)
        text = _frame_text
    else:
        out = explain_mode(_number(args.byte if args.byte is not None else args.control_mode, "control mode byte",
                                   0xFF), args.profile)
        text = _mode_text
    if args.json:
        json.dump(out, sys.stdout, indent=2)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(text(out))
    return 0


# ---- the control mode byte -------------------------------------------------------------


def explain_mode(byte: int, profile: str | None = None) -> dict[str, Any]:
    rules = default_rules()
    cm = rules.data["control_mode"]
    raw = rules.decode_control_mode(byte)
    fields = []
    for f in cm["fields"]:
        value = raw[f["name"]]
        hi = f["lsb"] + f["width"] - 1
        name = next((v["name"] for v in f["values"] if v["value"] == value), None)
        undefined = next((u for u in f["undefined"] if u["value"] == value), None)
        fields.append({"field": f["name"], "bits": f"{hi}:{f['lsb']}" if f["width"] > 1 else str(hi),
                       "value": value, "name": name,
                       **({"undefined": undefined["classification"], "reason": undefined["reason"]}
                          if undefined else {})})
    per_profile = {}
    for p in ([profile] if profile else profile_names()):
        c = rules.classify_control_mode(byte, p)
        ranges = rules.input_ranges(byte, p)
        per_profile[p] = {"classification": c["classification"], "combination": c["combination"],
                          "bit0": c["bit0"], "reasons": c["reasons"], "preconditions": c["preconditions"],
                          "ranges": _ranges(ranges, rules) if ranges else None}
    errata = sorted({e for p in per_profile.values() for r in p["reasons"] for e in _ERRATUM.findall(r)}
                    | {e for f in cm["fields"] for u in f["undefined"] if u["value"] == raw[f["name"]]
                       for e in _ERRATUM.findall(u["source"])}
                    | set(_ERRATUM.findall(cm["source"])))
    return {"byte": byte, "hex": f"0x{byte:02X}", "binary": f"0b{byte:08b}", "fields": fields,
            "frame": _frame_meaning(raw, cm), "profiles": per_profile, "errata": _errata_titles(errata)}


def _ranges(ranges: dict, rules) -> dict:
    axes = rules.data["control_modes"]["axes"]
    out = {}
    for part in ("horizontal", "vertical", "yaw"):
        r = ranges[part]
        out[part] = {"axes": axes[part], "min": r.get("min"), "max": r.get("max"), "unit": r["unit"],
                     **({"max_ref": r["max_ref"]} if r.get("max_ref") else {}),
                     **({"note": r["note"]} if r.get("note") else {})}
    return out


def _frame_meaning(raw: dict[str, int], cm: dict) -> str:
    frame = {0: "ground", 1: "body"}.get(raw["horizontal_frame"])
    horizontal = f"horizontal setpoints in the {frame} frame" if frame else "no defined horizontal frame"
    if raw["yaw_logic"] == 0 and cm["yaw_angle_forces_ground_frame"]["value"]:
        return horizontal + "; yaw angle is referenced to the ground frame whatever the frame bits say"
    return horizontal


def _errata_titles(ids: list[str]) -> list[dict[str, str]]:
    text = (ROOT / "spec" / "ERRATA.md").read_text(encoding="utf-8")
    titles = dict(re.findall(r"^## (E\d+): (.*)$", text, re.M))
    known = errata_ids()
    return [{"id": e, "title": titles.get(e, "")} for e in ids if e in known]


def _mode_text(out: dict) -> str:
    lines = [f"control mode byte {out['hex']} = {out['binary']}", ""]
    for f in out["fields"]:
        what = f["name"] or f"undefined ({f['undefined']}: {f['reason']})"
        lines.append(f"  bit {f['bits']:4} {f['field']:18} {f['value']}  {what}")
    lines += ["", f"  {out['frame']}", ""]
    for p, c in out["profiles"].items():
        combo = f", combination {c['combination']} of the seed's table" if c["combination"] else ""
        lines.append(f"{p}: {c['classification'].upper()}{combo}; bit 0 is {c['bit0']['meaning']} "
                     f"({c['bit0']['name']})")
        for r in c["reasons"]:
            lines.append(f"    {r}")
        for part, r in (c["ranges"] or {}).items():
            bound = f"{_num(r['min'])} to {_num(r['max']) if r['max'] is not None else r.get('max_ref', 'no limit')}"
            lines.append(f"    {part:10} {', '.join(r['axes']):24} {bound} {r['unit']}"
                         + (f" ({r['note']})" if r.get("note") else ""))
        if c["preconditions"]:
            lines.append(f"    preconditions: {', '.join(c['preconditions'])}")
    if out["errata"]:
        lines += ["", "errata: " + "; ".join(f"{e['id']} {e['title']}" for e in out["errata"])]
    return "\n".join(lines) + "\n"


def _num(v) -> str:
    return "no limit" if v is None else f"{v:g}"


# ---- ACK codes ---------------------------------------------------------------------------


def explain_ack(command: str, code_text: str) -> dict[str, Any]:
    name = _command(command)
    enum = ACK_ENUMS.get(name)
    if enum is None:
        raise UsageError(f"{command}: the spec gives no ACK codes for {name} (commands with codes: "
                         f"{', '.join(ACK_ENUMS)})")
    code = _number(code_text, "ACK code", 0xFFFF)
    block = default_rules().data["enums"][enum]
    row = next((v for v in block["values"] if v["value"] == code), None)
    out = {"command": name, "enum": enum, "code": code, "hex": f"0x{code:04X}", "source": block["source"]}
    if row is None:
        out.update({"name": None, "meaning": f"code {code} is not defined by the spec for {name}",
                    "defined": [v["value"] for v in block["values"]]})
    else:
        out.update({"name": row["name"], "meaning": row.get("meaning", ""), "remedy": row.get("remedy", ""),
                    "remedy_source": row.get("remedy_source", "")})
    return out


def _command(text: str) -> str:
    if text in COMMANDS.values():
        return text
    m = re.fullmatch(r"\s*(0x[0-9a-fA-F]+|\d+)\s*,\s*(0x[0-9a-fA-F]+|\d+)\s*", text)
    if m and (int(m.group(1), 0), int(m.group(2), 0)) in COMMANDS:
        return COMMANDS[(int(m.group(1), 0), int(m.group(2), 0))]
    raise UsageError(f"unknown command {text!r} (known: {', '.join(COMMANDS.values())}, or SET,ID)")


def _ack_text(out: dict) -> str:
    head = f"{out['command']} ACK {out['hex']} ({out['code']})"
    if out["name"] is None:
        return f"{head}: {out['meaning']} (defined: {', '.join(map(str, out['defined']))})\n"
    return (f"{head}: {out['name']}\n  meaning: {out['meaning']}\n  remedy:  {out['remedy']}\n"
            f"  source:  {out['remedy_source']}\n")


# ---- a frame -----------------------------------------------------------------------------


# What the receiver does after each error class (core/deframe.py: a bad header costs one byte and
# the hunt for 0xAA goes on; a bad CRC-32 rescans from the byte after the rejected start).
AFTER = {"bad_sof": "drops the byte and hunts for the next 0xAA",
         "truncated_frame": "waits for the rest of the frame (a stream's end loses it)",
         "bad_crc32": "rescans from the byte after the rejected start, so a frame inside it is still found"}
HEADER_ERRORS = ("bad_crc16", "bad_version", "reserved_bits", "impossible_length")


def explain_frame(raw: bytes, profile: str | None) -> dict[str, Any]:
    """The frame field by field; the verdict is the reference decoder's (decode_frame, the operation the
    vectors pin), so this explains the spec's decision and does not take one of its own."""
    answer = codec.answer("decode_frame", profile or "a3-fw3.1", {"hex": raw.hex()})
    out: dict[str, Any] = {"bytes": len(raw), "profile": profile or "a3-fw3.1", "fields": _header(raw),
                           "verdict": "valid" if answer["ok"] else "rejected", "breaks_at": None}
    if answer["ok"]:
        frame = answer["result"]["frame"]
        out["data"] = frame.get("data")
        if "crc32" in frame:
            out["fields"].append({"field": "CRC32", "bytes": f"{frame['len'] - 4}-{frame['len'] - 1}",
                                  "value": f"0x{frame['crc32']:08X}"})
        if profile is None and _is_broadcast(frame):
            out["note"] = "a broadcast decoded as a3-fw3.1: give --profile for another layout"
        return out
    error = answer["error"]
    after = AFTER.get(error) or ("drops the first byte and hunts for the next 0xAA" if error in HEADER_ERRORS
                                 else "drops the frame (its header and CRCs were good: the hunt goes on after it)")
    out["breaks_at"] = {"error": error, "detail": answer.get("detail", ""), "receiver": after}
    return out


def _is_broadcast(frame: dict) -> bool:
    data = frame.get("data") or {}
    cmd = data.get("cmd_set")
    return isinstance(cmd, dict) and cmd.get("value") == 2 and data.get("cmd_id") == 0


def _header(raw: bytes) -> list[dict]:
    if len(raw) < HEADER_LEN:
        return []
    h = header_fields(raw[:HEADER_LEN])
    return [
        {"field": "SOF", "bytes": "0", "value": f"0x{raw[0]:02X}"},
        {"field": "LEN", "bytes": "1-2, 10 bits", "value": h["len"]},
        {"field": "VER", "bytes": "2, 6 bits", "value": h["ver"]},
        {"field": "SESSION", "bytes": "3, 5 bits", "value": h["session"]},
        {"field": "ACK", "bytes": "3, 1 bit", "value": int(h["is_ack"])},
        {"field": "RES0", "bytes": "3, 2 bits", "value": h["res0"]},
        {"field": "PADDING", "bytes": "4, 5 bits", "value": h["padding"]},
        {"field": "ENC", "bytes": "4, 3 bits", "value": h["enc"]},
        {"field": "RES1", "bytes": "5-7", "value": h["res1"]},
        {"field": "SEQ", "bytes": "8-9", "value": h["seq"]},
        {"field": "CRC16", "bytes": "10-11", "value": f"0x{h['crc16']:04X}", "computed": f"0x{crc16(raw[:10]):04X}"},
    ]


def _frame_text(out: dict) -> str:
    lines = [f"{out['bytes']} bytes, {out['profile']}: {out['verdict'].upper()}"]
    for f in out["fields"]:
        extra = f"  (computed {f['computed']})" if "computed" in f and f["computed"] != f["value"] else ""
        lines.append(f"  {f['field']:8} byte {f['bytes']:14} {f['value']}{extra}")
    if out["breaks_at"]:
        b = out["breaks_at"]
        lines.append(f"breaks at: {b['error']}: {b['detail']}; the receiver {b['receiver']}")
    if out.get("data") is not None:
        lines.append("DATA: " + json.dumps(out["data"]))
    if out.get("note"):
        lines.append(out["note"])
    return "\n".join(lines) + "\n"


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
    data = parse_hex(text)
    if len(data) > MAX_LEN + 64:
        raise UsageError(f"--hex: {len(data)} bytes; one frame is at most {MAX_LEN}")
    return data

