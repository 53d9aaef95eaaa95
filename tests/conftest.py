"""Hypothesis settings profiles for the whole test suite.

"ci" is the default, what `make test` runs: a smoke run of 100 examples
per property (the differential tests: per message type), derandomized so
that a CI run can be repeated exactly and stays within the suite's
10-minute budget. "campaign" is the long run of `make properties`: 10,000
examples per property, randomized, so each campaign explores new inputs (a
failure prints its reproducing example and seed). "dev" is a quick pass
for local work (`make quick`). Choose with the environment
variable OSDK_HYPOTHESIS_PROFILE (e.g. OSDK_HYPOTHESIS_PROFILE=dev).
No deadline: example cost varies with message size, and a slow example is
not a failure of the spec.
"""
from __future__ import annotations

import os

from hypothesis import HealthCheck, settings

settings.register_profile(
    "ci",
    max_examples=100,
    deadline=None,
    derandomize=True,
    database=None,  # derandomized runs neither need nor should leave an example database
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile(
    "campaign",
    max_examples=10_000,
    deadline=None,
    database=None,  # nothing is written into the checkout; a failure prints how to reproduce it
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile(
    "dev",
    max_examples=50,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.load_profile(os.environ.get("OSDK_HYPOTHESIS_PROFILE", "ci"))


# The longest test files (their summed `--durations` in a `make test` run on
# 2 cores), longest first. pytest-xdist hands whole files to its workers in
# collection order, so the long ones start first and the run ends on short
# files on both workers, not on one worker finishing a long file alone.
# Only the order changes; no test depends on it.
LONGEST_FIRST = (
    "test_bounded_memory.py", "test_runner.py", "test_wheel.py", "test_selftest.py", "test_vectors.py",
    "test_extending.py", "test_fuzz.py", "test_languages.py", "test_fuzz_targets.py",
    "test_kaitai_vs_construct.py", "test_readme_snippets.py", "test_wireshark.py", "test_device_fuzz.py",
    "test_interrupt.py", "test_lone_clone.py",
)


def pytest_collection_modifyitems(session, config, items) -> None:
    rank = {name: i for i, name in enumerate(LONGEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))  # stable: a file keeps its order
