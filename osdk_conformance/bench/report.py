"""What `osdkc bench` prints: the terminal tables, the Markdown block for
docs/PERFORMANCE.md, and the verdict on each target of the issue."""
from __future__ import annotations

import re
from pathlib import Path

from osdk_conformance.bench.decode import BASELINE
from osdk_conformance.bench.reliability import summary

BEGIN = "<!-- bench:begin (osdkc bench --markdown writes this part) -->"
END = "<!-- bench:end -->"
HOUR_CORPUS, HOUR = "a3-hour", 3600.0
PYTHON_IMPLS = ("construct", "kaitai-python")


def _num(x, fmt: str = "{:,.0f}") -> str:
    return "–" if x is None else fmt.format(x)


def _ratio(x) -> str:
    if x is None:
        return "–"
    return f"{x:.3f}×" if x < 0.1 else f"{x:.2f}×"   # the slow ones still differ from each other


def _corpus_title(c: dict, repeats: int) -> str:
    e = c.get("expected")
    what = (f"{e['frames']:,} frames, {e['errors']} errors, {e['garbage_bytes']:,} garbage bytes" if e
            else "content unknown: counts checked between implementations")
    length = f"{c['corpus_seconds']:g} s of traffic, " if c.get("corpus_seconds") else ""
    return f"{c['name']} ({c['profile']}, {length}{c['bytes'] / 1e6:.1f} MB, {what}); best of up to {repeats} runs"


DECODE_COLUMNS = ("implementation", "runs", "seconds", "frames/s", "MB/s", "peak RSS MiB", "vs baseline")


def _decode_cells(r: dict) -> list[str]:
    if not r.get("ok"):
        return [r["impl"], str(r.get("runs", 0)), f"ERROR: {r.get('error', 'no result')}"]
    return [r["impl"], str(r["runs"]), f"{r['seconds']:.3f}", _num(r["frames_per_s"]), _num(r["mb_per_s"], "{:,.1f}"),
            _num(r["peak_rss_mib"], "{:,.1f}"), _ratio(r["ratio_to_baseline"])]


# ---- targets ----------------------------------------------------------------------------------


def _hour_seconds(decode: dict | None, impl: str) -> tuple[float | None, str]:
    """An implementation's seconds for the one-hour corpus, extrapolated when a shorter one ran."""
    for c in (decode or {}).get("corpora", []):
        if c["name"] != HOUR_CORPUS:
            continue
        r = next((r for r in c["results"] if r["impl"] == impl and r.get("ok")), None)
        if r is None:
            return None, ""
        if c["corpus_seconds"] == HOUR:
            return r["seconds"], ""
        return r["seconds"] * HOUR / c["corpus_seconds"], f" (extrapolated from {c['corpus_seconds']:g} s)"
    return None, ""


def recommended_python(decode: dict | None) -> str | None:
    """The faster Python implementation on the one-hour corpus."""
    timed = [(s, impl) for impl in PYTHON_IMPLS for s, _ in [_hour_seconds(decode, impl)] if s is not None]
    return min(timed)[1] if timed else None


def targets(result: dict) -> list[dict]:
    decode, out = result.get("decode"), []
    ratios = [(r["ratio_to_baseline"], c["name"]) for c in (decode or {}).get("corpora", [])
              for r in c["results"] if r["impl"] == "c" and r.get("ratio_to_baseline") is not None]
    out.append({"target": "generated C decoder (fully bounds-checked) at ≥ 50% of the memcpy baseline's throughput",
                "measured": ", ".join(f"{_ratio(x)} on {n}" for x, n in ratios) or "not measured",
                "met": min(x for x, _ in ratios) >= 0.5 if ratios else None})
    best = recommended_python(decode)
    secs, note = _hour_seconds(decode, best) if best else (None, "")
    out.append({"target": "recommended Python implementation decodes the one-hour a3-fw3.1 corpus in < 10 s",
                "measured": f"{best}: {secs:.1f} s{note}" if best else "not measured",
                "met": secs < 10 if best else None})
    out += _api_targets(result.get("api"))
    run = result.get("run")
    out.append({"target": "`osdkc run --impl all` in < 60 s on 2 cores",
                "measured": (f"{run['wall_seconds']} s wall, {run['cpu_seconds']} s CPU, {run.get('jobs', '?')} "
                             "implementations at a time") if run else "not measured",
                "met": (run["wall_seconds"] < 60 and run["ok"]) if run else None})
    acc = result.get("acceptance")
    cpu = acc.get("receiver_cpu_percent") if acc else None
    out.append({"target": "acceptance receiver < 5% of one core at 100 Hz",
                "measured": f"{cpu}% of one core" if cpu is not None else "not measured",
                "met": cpu < 5 if cpu is not None else None})
    out += _device_fuzz_targets(result.get("device_fuzz"))
    out += _reliability_targets(result.get("reliability"))
    out += _board_targets((result.get("footprint") or {}).get("board"))
    return out


def _board_targets(board: dict | None) -> list[dict]:
    """Issue 30's receive-only goals, on the whole linked program (footprint section, board_footprint.py)."""
    if board is None:
        return []
    where = f"receive-only program linked for {board.get('board')} (Cortex-M4, -Os, newlib-nano)"
    if not board.get("ok"):
        return [{"target": f"{where}: flash < 8 KiB, RAM with stack < 1 KiB",
                 "measured": f"FAILED: {board.get('error')}", "met": False}]
    g = board["goals"]
    return [{"target": f"{where}: flash < 8 KiB", "measured": f"{g['flash']['measured']} bytes",
             "met": g["flash"]["met"]},
            {"target": f"{where}: RAM including the stack < 1 KiB", "measured": f"{g['ram']['measured']} bytes",
             "met": g["ram"]["met"]}]


def _device_fuzz_targets(dfz: dict | None) -> list[dict]:
    """The issue asks for the number, with no speed to reach: its verdict says so instead of met or missed."""
    if dfz is None:
        return []
    rows = [r for r in dfz["rows"] if "cases_per_s" in r]
    measured = "; ".join(f"{r['cases_per_s']:,.0f} cases/s at {r['baud']} baud"
                         + (f" ({r['share_of_line']:.0%} of what the line carries)" if "share_of_line" in r else "")
                         for r in rows) or "not measured"
    failed = [f"{r['baud']} baud: {r['error']}" for r in dfz["rows"] if not r["ok"]]
    return [{"target": "`osdkc fuzz --port`: cases per second over a pty at "
                       + " and ".join(str(r["baud"]) for r in dfz["rows"]) + " baud",
             "measured": measured + (f"; FAILED: {'; '.join(failed)}" if failed else ""),
             "met": None if dfz["ok"] else False, "verdict": "reported, no target" if dfz["ok"] else None}]


def _api_row(api: dict, decoder: str) -> tuple[dict | None, float]:
    """The row of one decoder, and the factor from its corpus to one hour."""
    row = next((r for r in api["rows"] if r["decoder"] == decoder and "api_seconds" in r), None)
    return row, HOUR / api["corpus_seconds"]


def _api_targets(api: dict | None) -> list[dict]:
    if api is None:
        return []
    note = "" if api["corpus_seconds"] == HOUR else f" (extrapolated from {api['corpus_seconds']:g} s)"
    out = []
    for decoder, limit in (("native", 2.0), ("pure Python", 15.0)):
        row, k = _api_row(api, decoder)
        secs = row["api_seconds"] * k if row else None
        out.append({"target": f"one hour of a3-fw3.1 (360,000 frames, 78.5 MB) into Python values through the API, "
                              f"{decoder}, in < {limit:g} s",
                    "measured": f"{secs:.2f} s{note}" if secs is not None else "not measured",
                    "met": secs < limit if secs is not None else None})
    row, k = _api_row(api, "native")
    share = row.get("json_share") if row else None
    out.append({"target": "`osdkc decode` of that hour to JSON lines, native: limited by writing JSON (most of its time)",
                "measured": (f"{row['decode_json_seconds'] * k:.1f} s{note}, {share:.0%} of it writing JSON"
                             if share is not None else "not measured"),
                "met": share > 0.5 if share is not None else None})
    return out + _flight_targets(api.get("flight"))


def _flight_targets(fl: dict | None) -> list[dict]:
    if fl is None:
        return []
    k = HOUR / fl["corpus_seconds"]
    note = "" if fl["corpus_seconds"] == HOUR else f" (extrapolated from {fl['corpus_seconds']:g} s)"
    out = []
    for key, what, limit in (("table_seconds", "into an Arrow table (`api.table`, every column)", 0.5),
                             ("records_seconds", "into typed Python records (`api.broadcasts`, two fields read)", 2.0),
                             ("csv_seconds", "through `osdkc decode --format csv` (start-up included)", 5.0)):
        secs = fl[key] * k if key in fl else None
        out.append({"target": f"one hour of a3-fw3.1 {what}, in < {limit:g} s",
                    "measured": f"{secs:.2f} s{note}" if secs is not None else f"not measured ({fl.get('error')})",
                    "met": secs < limit if secs is not None else None})
    return out


def _reliability_targets(rel: dict | None) -> list[dict]:
    if rel is None:
        return []
    h, faults = rel["healthy"], rel["faults"]
    fault_runs = min((f["runs"] for f in faults.values()), default=0)
    busy = (rel.get("load") or {}).get("busy_loops_per_core", 0)
    return [{"target": "0 FAILs in ≥ 200 runs (active and passive) against a healthy simulator, the machine "
                       "saturated (2 busy loops per core)",
             "measured": (f"{h['passed']} of {h['runs']} passed ({h['active']} active, {h['passive']} passive), "
                          f"{h['inconclusive']} inconclusive (host too busy), {h['false_fails']} with a FAIL, "
                          f"beside {busy} busy loops per core, {h['retransmissions']} retransmissions")
             if h["runs"] else "not measured",
             # no healthy run (--runs 0) measured nothing: not a miss. An inconclusive run blamed nobody;
             # the target is no false FAIL, and the inconclusive ones are in the line above for all to see
             # and a run whose simulated FC was itself starved measures the stand-in, not the judge
             "met": (h["runs"] >= 200 and busy >= 2 and h["false_fails"] == 0
                     and h["passed"] + h["inconclusive"] + h.get("stand_in_behind", 0) == h["runs"])
             if h["runs"] else None},
            {"target": "each simulator fault kind detected in every one of ≥ 20 seeded runs, under the same load",
             "measured": (f"{len(faults)} kinds: detected in {sum(f['detected'] for f in faults.values())} of "
                          f"{sum(f['runs'] for f in faults.values())} runs") if faults else "not measured",
             "met": (fault_runs >= 20 and all(not f["missed"] for f in faults.values())) if faults else None},
            *_fuzz_reliability_targets(rel.get("fuzz"), busy)]


def _fuzz_reliability_targets(fz: dict | None, busy: int) -> list[dict]:
    if not fz:
        return []
    bugs = fz["bugs"]
    return [{"target": "no false finding in ≥ 20 healthy osdkc fuzz --port sessions, the machine saturated",
             "measured": (f"{fz['clean']} of {fz['runs']} found nothing, {fz['inconclusive']} inconclusive (host too "
                          f"busy), {fz['false_findings']} with a false finding, beside {busy} busy loops per core")
             if fz["runs"] else "not measured",
             "met": (fz["runs"] >= 20 and busy >= 2 and fz["false_findings"] == 0 and not fz["failures"])
             if fz["runs"] else None},
            {"target": "each planted bug found and confirmed by the fuzzer in every one of ≥ 20 seeded sessions, "
                       "under the same load",
             "measured": (f"{len(bugs)} bugs: found in {sum(b['found'] for b in bugs.values())} of "
                          f"{sum(b['runs'] for b in bugs.values())} sessions") if bugs else "not measured",
             "met": (min(b["runs"] for b in bugs.values()) >= 20 and all(not b["missed"] for b in bugs.values()))
             if bugs else None}]


def _verdict(met) -> str:
    return "not measured" if met is None else "met" if met else "MISSED"


def _target_verdict(t: dict) -> str:
    return t.get("verdict") or _verdict(t["met"])


def _others(result: dict) -> list[tuple[str, str, str]]:
    rows = []
    if api := result.get("api"):
        for r in api["rows"]:
            text = (f"API {r['api_seconds']:.2f} s ({r['frames'] / r['api_seconds']:,.0f} frames/s); osdkc decode "
                    f"{r.get('decode_json_seconds', '–')} s" if "api_seconds" in r else "")
            rows.append((f"{api['corpus']} ({api['corpus_seconds']:g} s of traffic), {r['decoder']}",
                         f"OSDKC_ACCEL={'1' if r['decoder'] == 'native' else '0'} osdkc decode --profile "
                         f"{api['profile']} FILE", text + (f"; FAILED: {r['error']}" if "error" in r else "")))
        if fl := api.get("flight"):
            text = (f"best of {fl['runs']}: Arrow table {fl['table_seconds']:.2f} s ({fl['rows']:,} rows x "
                    f"{fl['columns']} columns); typed records {fl['records_seconds']:.2f} s; osdkc decode --format csv "
                    f"{fl.get('csv_seconds', '–')} s" if "table_seconds" in fl else "")
            rows.append((f"{fl['corpus']} ({fl['corpus_seconds']:g} s of traffic), flight data",
                         f"osdkc decode --profile {api['profile']} --format csv FILE",
                         text + (f"; FAILED: {fl['error']}" if "error" in fl else "")))
    if run := result.get("run"):
        per = ", ".join(f"{k} {v:.0f} s" for k, v in (run.get("per_impl_seconds") or {}).items() if v is not None)
        rows.append(("conformance run", run["command"],
                     f"{run['wall_seconds']} s wall, {run['cpu_seconds']} s CPU, {run.get('jobs', '?')} at a time"
                     + (f" ({per})" if per else "") + ("" if run["ok"] else f"; FAILED: {run.get('error')}")))
    if fz := result.get("fuzz"):
        text = (f"{fz['execs_per_s']} execs/s ({fz['examples']} examples in {fz['seconds']} s; per operation: "
                + ", ".join(f"{k} {v}" for k, v in fz.get("per_op_execs_per_s", {}).items()) + ")"
                if "execs_per_s" in fz else "")
        rows.append(("differential fuzzing, every bundled implementation", fz["command"],
                     text + ("" if fz["ok"] else f"; FAILED: {fz.get('error')}")))
    if acc := result.get("acceptance"):
        text = ""
        if acc.get("receiver_cpu_percent") is not None:
            lat = acc.get("latency_ms") or {}
            text = (f"{acc['receiver_cpu_percent']}% of one core over {acc['duration_s']} s; "
                    f"{acc['frames_lost']} of {acc['frames_sent']} frames lost; latency p50 {lat.get('p50')} ms, "
                    f"p99 {lat.get('p99')} ms")
        rows.append(("acceptance receiver, a3-fw3.1 every item at 100 Hz", acc["command"],
                     text + ("" if acc["ok"] else f"; FAILED: {acc.get('error')}")))
    if dfz := result.get("device_fuzz"):
        for r in dfz["rows"]:
            rows.append((f"device fuzzing, {dfz['profile']} simulator over a pty at {r['baud']} baud", r["command"],
                         _device_fuzz_text(r)))
    if rel := result.get("reliability"):
        rows.append(("reliability of osdkc device and osdkc fuzz --port: healthy runs, seeded faults and bugs",
                     rel["command"],
                     summary(rel) + f" ({rel['seconds']:.0f} s)"))
    return rows


def _device_fuzz_text(r: dict) -> str:
    text = ""
    if r.get("cases_per_s"):   # 0 when no case went out (the device was not live at the start)
        text = (f"{r['cases_per_s']:,.1f} cases/s ({r['cases']} cases: {r['cases'] / r['cases_per_s']:.1f} s sending "
                f"and checking them, {r['seconds']:g} s with the start-up check and clean-up)")
        if "bytes_per_case" in r:
            text += (f"; {r['bytes_per_case']:g} bytes sent per case, which the line carries at "
                     f"{r['line_cases_per_s']:,.0f} cases/s: {r['share_of_line']:.0%} of it")
        text += "; no finding" if not r["findings"] else f"; {r['findings']} finding(s)"
    return text + ("" if r["ok"] else f"; FAILED: {r.get('error')}")


# ---- terminal ---------------------------------------------------------------------------------


def _table(header: tuple[str, ...], rows: list[list[str]]) -> list[str]:
    width = [max([len(h)] + [len(r[i]) for r in rows if i < len(r) and len(r) == len(header)])
             for i, h in enumerate(header)]
    fmt = lambda cells: "  ".join(c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(cells, width)))
    lines = [fmt(header), "-" * (sum(width) + 2 * (len(width) - 1))]
    for r in rows:
        lines.append(fmt(r) if len(r) == len(header) else "  ".join([r[0].ljust(width[0]), r[1].rjust(width[1]), r[2]]))
    return lines


def terminal(result: dict) -> str:
    lines = [f"osdkc bench: {result['command']}"]
    if decode := result.get("decode"):
        for c in decode["corpora"]:
            lines += ["", "decode: " + _corpus_title(c, decode["repeats"])]
            lines += ["  " + ln for ln in _table(DECODE_COLUMNS, [_decode_cells(r) for r in c["results"]])]
        for m in decode["mismatches"]:
            lines.append(f"MISMATCH: {m}")
    for what, cmd, text in _others(result):
        lines += ["", f"{what}: {cmd}", f"  {text}"]
    lines += ["", "targets:"]
    lines += [f"  [{_target_verdict(t)}] {t['target']}: {t['measured']}" for t in result["targets"]]
    return "\n".join(lines)


# ---- Markdown ---------------------------------------------------------------------------------


def _md_table(header: tuple[str, ...], rows: list[list[str]], align: str) -> list[str]:
    out = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    for r in rows:
        cells = r if len(r) == len(header) else r + [""] * (len(header) - len(r))
        out.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
    return out


def markdown(result: dict) -> str:
    m = result["machine"]
    lines = [BEGIN, "", f"Command: `{result['command']}` (run {result['started']}, {result['total_seconds']:.0f} s).",
             "", "| machine | |", "|---|---|"]
    lines += [f"| {k.replace('_', ' ')} | {v} |" for k, v in m.items()]
    if decode := result.get("decode"):
        lines += ["", "### Decode throughput, deframing included", "",
                  f"Each implementation's bench mode (conformance/PROTOCOL.md); seconds are its read+deframe+decode "
                  f"loop, best of up to {decode['repeats']} interleaved runs; peak RSS is the whole process "
                  f"(runtime included); the ratio is MB/s against the `{BASELINE}` row of the same corpus."]
        for c in decode["corpora"]:
            lines += ["", f"**{_corpus_title(c, decode['repeats'])}**", ""]
            lines += _md_table(DECODE_COLUMNS, [[f"`{x[0]}`", *x[1:]] for x in map(_decode_cells, c["results"])],
                               ["---", "---:", "---:", "---:", "---:", "---:", "---:"])
        if decode["mismatches"]:
            lines += ["", "Count mismatches:", *[f"- {x}" for x in decode["mismatches"]]]
        else:
            lines += ["", "Every implementation reported the corpus generator's frame, error and garbage counts."]
    others = _others(result)
    if others:
        lines += ["", "### Conformance run, fuzzing, acceptance receiver", ""]
        lines += _md_table(("what", "command", "result"), [[w, f"`{c}`", t] for w, c, t in others], ["---"] * 3)
    lines += ["", "### Targets", ""]
    lines += _md_table(("target", "measured", "verdict"),
                       [[t["target"], t["measured"], _target_verdict(t)] for t in result["targets"]], ["---"] * 3)
    return "\n".join(lines + ["", END])


def write_markdown(path: Path, block: str, begin: str = BEGIN, end: str = END) -> None:
    """Replace the block between `begin` and `end` of `path` (docs/PERFORMANCE.md
    has the bench block and the footprint block); a file without it gets the
    block at its end, a missing file the block alone."""
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        text = ""
    if begin in text and end in text:
        text = re.sub(re.escape(begin) + r".*?" + re.escape(end), lambda _: block, text, flags=re.S)
    else:
        text = (text.rstrip("\n") + "\n\n" if text else "") + block + "\n"
    path.write_text(text, encoding="utf-8")
