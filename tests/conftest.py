"""Hypothesis settings profiles for the whole test suite.

"ci" is the default: the differential tests must see at least 10,000
examples per message type there, derandomized so that a CI run can be
repeated exactly. "dev" is a quick pass for local work. Choose with the
environment variable OSDK_HYPOTHESIS_PROFILE (e.g. OSDK_HYPOTHESIS_PROFILE=dev).
No deadline: example cost varies with message size, and a slow example is
not a failure of the spec.
"""
from __future__ import annotations

import os

from hypothesis import HealthCheck, settings

settings.register_profile(
    "ci",
    max_examples=10_000,
    deadline=None,
    derandomize=True,
    database=None,  # derandomized runs neither need nor should leave an example database
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile(
    "dev",
    max_examples=200,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.load_profile(os.environ.get("OSDK_HYPOTHESIS_PROFILE", "ci"))
