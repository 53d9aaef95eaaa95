"""Claims no operation (or, with --all, claims every operation and profile)
and answers `unsupported` to every case: nothing ever runs."""
import sys

from _common import CAPABILITIES, reply, requests

if "--all" not in sys.argv:
    CAPABILITIES["result"].update(operations=[], profiles=[])
for _ in requests():
    reply({"ok": False, "unsupported": True})
