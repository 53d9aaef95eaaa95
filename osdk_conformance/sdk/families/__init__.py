"""One module per family of DJI Onboard-SDK releases (osdk_conformance/sdk/family.py)."""
