"""The `api` section of `osdkc bench`: decoding through the public Python API
and `osdkc decode`, with the native accelerator and with pure Python.

For each decoder (OSDKC_ACCEL=1, then 0), in fresh interpreters:

- the API: USER_PROGRAM below, what a user writes to read a capture into
  Python values (`for ev in api.decode_file(path, profile)`), every event
  built and let go as the loop goes on. The imports, the rules and the
  first 256 KiB of the file (Construct compiles a parser after its first
  uses) are decoded before the clock starts; the seconds are the loop over
  the whole file;
- `osdkc decode --profile P FILE > /dev/null`: the command's wall time,
  start-up included, so the JSON text of every event is written.

The difference between the two is what writing JSON costs (`model.dumps`,
Python's json module): for the native decoder it is most of the command's
time, which is what the issue asks to measure and report.
"""
from __future__ import annotations

import json
import sys

from osdk_conformance.bench import child as bench_child
from osdk_conformance.bench.corpus import Corpus

# A separate program, as a user would write it: it imports only the public
# API (osdk_conformance.api sits above this layer of the package, and a
# fresh interpreter keeps the measurement free of this process's heap).
USER_PROGRAM = """
import json, sys, time
from osdk_conformance import api
from osdk_conformance.reference import accel
path, profile = sys.argv[1], sys.argv[2]
with open(path, "rb") as fh:
    api.decode(fh.read(256 * 1024), profile)
frames = events = 0
start = time.perf_counter()
for ev in api.decode_file(path, profile):
    events += 1
    frames += ev.kind == "frame"
seconds = time.perf_counter() - start
print(json.dumps({"decoder": accel.describe(), "events": events, "frames": frames, "seconds": seconds}))
"""

DECODERS = (("native", "1"), ("pure Python", "0"))


def measure(corpus: Corpus, timeout: float) -> dict:
    rows = []
    for name, switch in DECODERS:
        env = {"OSDKC_ACCEL": switch}
        row: dict = {"decoder": name}
        api_run = bench_child.run([sys.executable, "-c", USER_PROGRAM, corpus.path, corpus.profile], timeout, env=env)
        try:
            out = json.loads(api_run.stdout.strip().splitlines()[-1])
            row.update(api_seconds=round(out["seconds"], 3), frames=out["frames"], events=out["events"],
                       described=out["decoder"])
            if out["frames"] != corpus.frames:
                row["error"] = f"{out['frames']} frames, the corpus has {corpus.frames}"
        except (IndexError, ValueError, KeyError):
            row["error"] = api_run.problem or api_run.stderr_line() or f"exit {api_run.code}"
            rows.append(row)
            continue
        cli = bench_child.run([sys.executable, "-m", "osdk_conformance", "decode", "--profile", corpus.profile,
                               corpus.path], timeout, env=env, discard_stdout=True)
        # exit 1 means errors were reported as events, which a corpus with faults has
        if cli.code in (0, 1):
            row["decode_json_seconds"] = round(cli.wall, 3)
            row["json_share"] = round(max(0.0, 1 - row["api_seconds"] / cli.wall), 3) if cli.wall else None
        else:
            row["error"] = f"osdkc decode: {cli.problem or cli.stderr_line() or f'exit {cli.code}'}"
        rows.append(row)
    return {"corpus": corpus.name, "profile": corpus.profile, "corpus_seconds": corpus.seconds,
            "bytes": corpus.bytes, "frames": corpus.frames, "rows": rows,
            "ok": all("error" not in r for r in rows)}
