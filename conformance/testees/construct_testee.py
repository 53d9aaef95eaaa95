"""The bundled "construct" testee: answers every operation of
conformance/PROTOCOL.md with the reference answers
(osdk_conformance.reference.codec, built on the Construct spec).

    osdkc run --impl construct
    python conformance/testees/construct_testee.py   # speaks JSON Lines on stdin/stdout
    python conformance/testees/construct_testee.py --bench FILE --profile P

One request line in, one response line out, flushed. Input it cannot use
(not JSON, not an object, missing or ill-typed arguments) is answered with
error `bad_request`; an unexpected exception is answered with error
`internal_error` (a failed case, never a crash).

With arguments it runs the bench mode (osdk_conformance.harness.testee_bench) over
decode_stream's own event loop, decode.decode_events, value models included:
a broadcast layout seen before is decoded straight into its model
(reference/fastframe.py), which is faster than Construct's containers.
"""
from __future__ import annotations

import sys
from typing import Sequence


def main(argv: Sequence[str] = ()) -> int:
    if argv:
        from osdk_conformance.harness import testee_bench
        from osdk_conformance.reference.decode import decode_events
        from osdk_conformance.reference.codec import PROFILES

        return testee_bench.main(argv, "construct", PROFILES, decode_events)

    from osdk_conformance.reference.codec import answer
    from osdk_conformance.harness.serve import serve

    return serve(lambda req: answer(req["op"], req.get("profile"),
                                    {k: v for k, v in req.items() if k not in ("op", "id", "profile")}))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
