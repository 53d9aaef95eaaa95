"""Files the flight commands write: written beside their name and renamed
over it at the end, so an interrupted or failed write never leaves half a
table or half a page under the name a user asked for."""
from __future__ import annotations

import os
from typing import IO, Callable


def write_replacing(path: str | os.PathLike[str], write: Callable[[IO[bytes]], None]) -> None:
    """Calls `write` with a binary file beside `path`, then renames it to `path`.
    OSError when it cannot be written; then nothing is left behind."""
    target = os.fspath(path)
    tmp = f"{target}.partial"
    try:
        with open(tmp, "wb") as out:
            write(out)
        os.replace(tmp, target)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
