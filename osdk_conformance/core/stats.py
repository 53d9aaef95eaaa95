"""Statistics every layer reports in: one way to compute a percentile."""
from __future__ import annotations

import math


def percentile(values: list[float], p: float) -> float:
    """The p-th percentile (0..100) of `values`, interpolated linearly
    between the two nearest ranks; NaN for no values."""
    if not values:
        return float("nan")
    s = sorted(values)
    k = (len(s) - 1) * p / 100.0
    lo, hi = math.floor(k), math.ceil(k)
    return s[lo] + (s[hi] - s[lo]) * (k - lo)
