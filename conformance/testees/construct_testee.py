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

import sys


def main() -> int:
    from osdk_conformance.reference import answer
    from osdk_conformance.serve import serve

    return serve(lambda req: answer(req["op"], req.get("profile"),
                                    {k: v for k, v in req.items() if k not in ("op", "id", "profile")}))


if __name__ == "__main__":
    sys.exit(main())
