"""What this host knows about a serial port before a byte is read: does it
exist, may this user open it, which other process has it open (a second
program reading steals the flight controller's bytes; a getty answers them
with login prompts), and which serial devices exist instead."""
from __future__ import annotations

import glob
import grp
import os
import re
import stat
from dataclasses import dataclass, field
from pathlib import Path

# The device names a companion computer's UART or USB adapter gets: USB
# adapters (ttyUSB: FTDI/CP210x/CH340, ttyACM: CDC-ACM), Jetson (ttyTHS),
# Raspberry Pi (ttyAMA, ttyS0 on the Pi 3/4 mini UART), PC UARTs (ttyS).
CANDIDATE_GLOBS = ("/dev/serial/by-id/*", "/dev/ttyUSB*", "/dev/ttyACM*", "/dev/ttyTHS*", "/dev/ttyAMA*",
                   "/dev/ttyS[0-9]", "/dev/ttyS[0-9][0-9]")
# Programs that put a login console on a tty: agetty and friends, and login once a user name was typed.
CONSOLE_PROGRAMS = frozenset({"agetty", "getty", "mingetty", "mgetty", "fgetty", "serial-getty", "login"})
_URL = re.compile(r"^[a-z][a-z0-9+.-]*://")


@dataclass(frozen=True)
class Holder:
    pid: int
    program: str       # the kernel's name of the process (comm)
    command: str       # its command line

    @property
    def is_console(self) -> bool:
        return self.program in CONSOLE_PROGRAMS or Path(self.command.split(" ")[0]).name in CONSOLE_PROGRAMS

    def describe(self) -> str:
        return f"{self.program} (pid {self.pid}: {self.command[:80]})"


@dataclass
class PortFacts:
    name: str
    is_url: bool = False            # socket://, rfc2217://, ...: nothing local to look at
    exists: bool = True
    path: str = ""                  # the device node it resolves to
    readable: bool = True
    writable: bool = True
    owner_group: str | None = None  # the group that may open it (dialout, tty, uucp)
    in_group: bool = True           # whether this user is in that group
    is_serial: bool | None = None   # a terminal device (None: could not be told)
    holders: list[Holder] = field(default_factory=list)
    candidates: list[str] = field(default_factory=list)

    @property
    def allowed(self) -> bool:
        return self.readable and self.writable


def candidates() -> list[str]:
    """Serial devices present on this host, by-id names first (they survive re-plugging)."""
    out: list[str] = []
    for pattern in CANDIDATE_GLOBS:
        for p in sorted(glob.glob(pattern)):
            if p not in out:
                out.append(p)
    return out


def inspect(name: str) -> PortFacts:
    facts = PortFacts(name)
    if _URL.match(name):
        facts.is_url = True
        return facts
    if not os.path.exists(name):
        facts.exists = False
        facts.candidates = candidates()
        return facts
    facts.path = os.path.realpath(name)
    facts.readable = os.access(facts.path, os.R_OK)
    facts.writable = os.access(facts.path, os.W_OK)
    try:
        st = os.stat(facts.path)
        facts.owner_group = grp.getgrgid(st.st_gid).gr_name
        facts.in_group = st.st_gid in os.getgroups() or st.st_gid == os.getgid()
        facts.is_serial = stat.S_ISCHR(st.st_mode) and _is_terminal(facts.path)
        if facts.is_serial is False:
            facts.candidates = candidates()
    except (OSError, KeyError):
        pass
    facts.holders = holders(facts.path)
    return facts


def _is_terminal(path: str) -> bool | None:
    """Whether the character device is a terminal (a serial port or a pseudo-terminal); None when it
    cannot be opened to tell. Opened without becoming its controlling terminal, and closed at once."""
    try:
        fd = os.open(path, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
    except OSError:
        return None
    try:
        return os.isatty(fd)
    finally:
        os.close(fd)


def holders(device: str) -> list[Holder]:
    """Other processes with `device` open. For a pseudo-terminal, the process
    holding its master (what stands in for the flight controller there, e.g.
    `osdkc sim`) is the other end of the line, not a competitor."""
    index = _pty_index(device)
    me = os.getpid()
    found = []
    for pid_dir in glob.glob("/proc/[0-9]*"):
        pid = int(pid_dir[6:])
        if pid == me:
            continue
        fds = _fds(pid_dir)
        if device not in fds.values():
            continue
        if index is not None and _holds_master(pid_dir, fds, index):
            continue
        found.append(Holder(pid, _read(f"{pid_dir}/comm").strip(),
                            _read(f"{pid_dir}/cmdline").replace("\0", " ").strip()))
    return found


def _pty_index(device: str) -> int | None:
    m = re.fullmatch(r"/dev/pts/(\d+)", device)
    return int(m.group(1)) if m else None


def _fds(pid_dir: str) -> dict[str, str]:
    out = {}
    try:
        for fd in os.listdir(f"{pid_dir}/fd"):
            try:
                out[fd] = os.readlink(f"{pid_dir}/fd/{fd}")
            except OSError:
                pass
    except OSError:   # another user's process, or gone
        pass
    return out


def _holds_master(pid_dir: str, fds: dict[str, str], index: int) -> bool:
    for fd, target in fds.items():
        if target in ("/dev/ptmx", "/dev/pts/ptmx"):
            info = _read(f"{pid_dir}/fdinfo/{fd}")
            m = re.search(r"^tty-index:\s*(\d+)", info, re.M)
            if m is None or int(m.group(1)) == index:   # an old kernel does not say which: assume this one
                return True
    return False


def _read(path: str) -> str:
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read()
    except OSError:
        return ""
