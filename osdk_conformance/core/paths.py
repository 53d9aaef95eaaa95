"""Where the parts of the repository are, so no module guesses."""
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SPEC = ROOT / "spec"

# The seed that spec/trace.yaml maps is a source, not part of the repository:
# the trace cites it by name and SHA-256. `osdkc spec trace --seed FILE` (and
# `spec check`, `kit`) read it from the file given, else from this variable;
# without either, the checks against the seed are skipped and say so.
SEED_ENV = "OSDK_SEED"
