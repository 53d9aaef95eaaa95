"""Where the parts of the repository are, so no module guesses."""
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec"
SEED = ROOT.parent / "shared" / "seeds" / "000_b7658b258220b5c1.txt"
FACTS = ROOT.parent / "shared" / "reference" / "PROTOCOL-FACTS.md"
