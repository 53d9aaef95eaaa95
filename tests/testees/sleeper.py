"""Answers capabilities, then never answers anything else."""
import time

from _common import requests

for _ in requests():
    time.sleep(3600)
