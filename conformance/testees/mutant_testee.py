"""A deliberately broken testee, for `osdkc selftest`: the bundled
"construct" testee (osdk_conformance.reference.codec) with ONE fault injected for
the life of the process, chosen by name from osdk_conformance.harness.mutants.

    python conformance/testees/mutant_testee.py MUTANT_NAME   # speaks JSON Lines
    python conformance/testees/mutant_testee.py none          # no fault (baseline)
    python conformance/testees/mutant_testee.py --list        # the mutants

`osdkc run --testee "python conformance/testees/mutant_testee.py crc16_init_ffff"`
must not conform; `osdkc selftest` checks that for every mutant.
"""
from __future__ import annotations

import sys
from pathlib import Path


def main(argv: list[str]) -> int:
    from osdk_conformance.harness import mutants

    if argv == ["--list"]:
        for m in mutants.MUTANTS.values():
            print(f"{m.name:32} {m.description}")
        return 0
    if len(argv) != 1:
        print("usage: mutant_testee.py MUTANT_NAME | none | --list", file=sys.stderr)
        return 2
    name = argv[0]
    if name != mutants.NONE and name not in mutants.MUTANTS:
        print(f"mutant_testee.py: no mutant {name!r} (see --list)", file=sys.stderr)
        return 2
    mutants.apply(name)

    from osdk_conformance.reference import codec as reference

    original = reference.answer

    def answer(op, profile, input):  # noqa: A002 - the protocol's word
        res = original(op, profile, input)
        if op == "capabilities" and res.get("ok"):
            res["result"] = dict(res["result"], name=f"mutant:{name}")
        return res

    reference.answer = answer

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import construct_testee

    return construct_testee.main()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
