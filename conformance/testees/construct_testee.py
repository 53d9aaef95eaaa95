"""The bundled "construct" testee: answers every operation of
conformance/PROTOCOL.md with the reference answers
(osdk_conformance.reference, built on the Construct spec).

    osdkc run --impl construct
    python conformance/testees/construct_testee.py   # speaks JSON Lines on stdin/stdout

One request line in, one response line out, flushed. Input it cannot use
(not JSON, not an object, missing or ill-typed arguments) is answered with
error `bad_request`; an unexpected exception is answered with error
`internal_error` (a failed case, never a crash).
"""
from __future__ import annotations

import json
import sys


def main() -> int:
    from osdk_conformance import model
    from osdk_conformance.reference import BadRequest, answer

    out = sys.stdout
    for line in sys.stdin:
        if not line.strip():
            continue
        try:
            req = json.loads(line)
            if not isinstance(req, dict) or not isinstance(req.get("op"), str):
                raise BadRequest('a request is a JSON object with an "op" string')
            args = {k: v for k, v in req.items() if k not in ("op", "id", "profile")}
            res = answer(req["op"], req.get("profile"), args)
        except (ValueError, RecursionError) as e:  # BadRequest, and JSON that does not parse
            res = {"ok": False, "error": "bad_request", "detail": f"{type(e).__name__}: {e}"}
        except Exception as e:  # a bug of ours: a failed case, not a dead testee
            res = {"ok": False, "error": "internal_error", "detail": f"{type(e).__name__}: {e}"}
        try:
            text = model.dumps(res)
        except (TypeError, ValueError) as e:
            text = json.dumps({"ok": False, "error": "internal_error", "detail": f"unserialisable answer: {e}"})
        out.write(text + "\n")
        out.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
