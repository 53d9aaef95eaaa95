"""`python -m osdk_conformance`: the same as `osdkc`."""
from osdk_conformance.cli import main

raise SystemExit(main())
