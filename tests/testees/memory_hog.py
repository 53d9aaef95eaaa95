"""Answers capabilities, then allocates memory without bound."""
from _common import requests

hoard = []
for _ in requests():
    while True:
        hoard.append(bytearray(16 * 1024 * 1024))
