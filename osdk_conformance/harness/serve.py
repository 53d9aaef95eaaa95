"""The request loop every bundled testee runs (conformance/PROTOCOL.md):
one JSON line in, one JSON line out, flushed. Input a testee cannot use is
answered `bad_request`, a bug of its own `internal_error`: a failed case,
never a dead testee."""
from __future__ import annotations

import json
import sys
from typing import Callable

from osdk_conformance.core import model


def serve(answer: Callable[[dict], dict]) -> int:
    """Answer every request on stdin with `answer(request)`. `answer` raises
    ValueError (or RecursionError) for a request it cannot use."""
    out = sys.stdout
    for line in sys.stdin:
        if not line.strip():
            continue
        try:
            req = json.loads(line)
            if not isinstance(req, dict) or not isinstance(req.get("op"), str):
                raise ValueError('a request is a JSON object with an "op" string')
            res = answer(req)
        except (ValueError, RecursionError) as e:  # bad requests, and JSON that does not parse
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
