"""Benchmarks (`osdkc bench`): decode speed against an SDK-style C baseline,
conformance run and fuzzing throughput, soak, reliability of the verdicts."""
