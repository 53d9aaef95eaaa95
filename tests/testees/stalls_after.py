"""Answers like the reference for its first N case requests, then starts a
child in its own process group, writes "PID PGID CHILD_PID" to MARKER and
never answers again: a run to interrupt at a known point, with a grandchild
that must not outlive the run.

usage: stalls_after.py N MARKER
"""
import json
import os
import subprocess
import sys
import time

from osdk_conformance.core import model
from osdk_conformance.reference.codec import request_answer

answered, limit, marker = 0, int(sys.argv[1]), sys.argv[2]
for line in sys.stdin:
    req = json.loads(line)
    if req.get("op") != "capabilities":
        if answered == limit:
            child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(3600)"])
            with open(marker + ".tmp", "w") as f:
                f.write(f"{os.getpid()} {os.getpgid(0)} {child.pid}\n")
            os.rename(marker + ".tmp", marker)  # the test sees the whole line or nothing
            time.sleep(3600)
        answered += 1
    print(model.dumps(request_answer(req)), flush=True)
