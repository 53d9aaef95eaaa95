"""Answers like the reference, except for the case ids given as arguments,
which it answers with an error class no vector expects."""
import json
import sys

from osdk_conformance.core import model
from osdk_conformance.reference.codec import answer

WRONG = set(sys.argv[1:])

for line in sys.stdin:
    req = json.loads(line)
    if req.get("id") in WRONG:
        res = {"ok": False, "error": "deliberately_wrong", "detail": "this testee breaks this case on purpose"}
    else:
        res = answer(req["op"], req.get("profile"), {k: v for k, v in req.items() if k not in ("op", "id", "profile")})
    print(model.dumps(res), flush=True)
