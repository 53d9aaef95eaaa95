"""Answers capabilities, then exits on the first real request."""
import sys

from _common import requests

for _ in requests():
    print("exit_first: giving up", file=sys.stderr, flush=True)
    sys.exit(3)
