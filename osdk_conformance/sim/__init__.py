"""`osdkc sim`: a simulated flight controller on a pseudo-terminal or TCP port."""
