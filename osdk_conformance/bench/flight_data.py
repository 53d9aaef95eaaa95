"""Flight data for people, measured in the `api` section of `osdkc bench`:
the corpus into an Arrow table, into typed records, and `osdkc decode
--format csv`, each in a fresh interpreter as a user runs it.

- table: `api.table(path, profile)`, every column of every broadcast; the
  imports and a first table of the first 256 KiB (pyarrow sets itself up on
  its first use) come before the clock starts;
- records: `for b in api.broadcasts(path, profile)`, reading two fields of
  each (the battery and a quaternion float), the columns filled inside the
  clock;
- csv: `osdkc decode --format csv FILE > /dev/null`, the command's wall
  time, start-up included.

Each is the best of REPEATS runs, as the decode section takes the best of
its runs: on a shared machine one run can take twice as long as the next.
"""
from __future__ import annotations

import json
import sys

from osdk_conformance.bench import child as bench_child
from osdk_conformance.bench.corpus import Corpus

REPEATS = 3

PROGRAM = """
import json, sys, time
from osdk_conformance import api
path, profile = sys.argv[1], sys.argv[2]
with open(path, "rb") as fh:
    api.table(fh.read(256 * 1024), profile)
start = time.perf_counter()
table = api.table(path, profile)
table_s = time.perf_counter() - start
start = time.perf_counter()
rows = 0
battery = 0
q0 = 0.0
for b in api.broadcasts(path, profile):
    rows += 1
    battery += b.battery or 0
    q0 += b.quaternion.q0 if b.quaternion is not None else 0.0
records_s = time.perf_counter() - start
print(json.dumps({"rows": table.num_rows, "columns": table.num_columns, "table_seconds": table_s,
                  "records": rows, "records_seconds": records_s}))
"""


def measure(corpus: Corpus, timeout: float, repeats: int = REPEATS) -> dict:
    out: dict = {"corpus": corpus.name, "corpus_seconds": corpus.seconds, "frames": corpus.frames, "runs": 0}
    for _ in range(repeats):
        run = bench_child.run([sys.executable, "-c", PROGRAM, corpus.path, corpus.profile], timeout,
                              env={"OSDKC_ACCEL": "1"})
        try:
            got = json.loads(run.stdout.strip().splitlines()[-1])
        except (IndexError, ValueError):
            out["error"] = run.problem or run.stderr_line() or f"exit {run.code}"
            break
        if got["rows"] != corpus.frames or got["records"] != corpus.frames:
            out["error"] = f"{got['rows']} rows and {got['records']} records, the corpus has {corpus.frames} frames"
            break
        out["runs"] += 1
        out.update(rows=got["rows"], columns=got["columns"])
        for key in ("table_seconds", "records_seconds"):
            out[key] = round(min(out.get(key, float("inf")), got[key]), 3)
    if "error" not in out:
        for _ in range(repeats):
            cli = bench_child.run([sys.executable, "-m", "osdk_conformance", "decode", "--profile", corpus.profile,
                                   "--format", "csv", corpus.path], timeout, env={"OSDKC_ACCEL": "1"},
                                  discard_stdout=True)
            if cli.code not in (0, 1):
                out["error"] = f"osdkc decode --format csv: {cli.problem or cli.stderr_line() or f'exit {cli.code}'}"
                break
            out["csv_seconds"] = round(min(out.get("csv_seconds", float("inf")), cli.wall), 3)
    out["ok"] = "error" not in out
    return out
