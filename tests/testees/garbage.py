"""Answers capabilities, then prints a line that is not JSON."""
import sys

from _common import requests

for req in requests():
    sys.stdout.write(f"hello, this is not JSON ({req.get('id')})\n")
    sys.stdout.flush()
