"""`osdkc tap`: the host a user brings, judged from between it and the flight controller (relay), or
from the two RX taps of a Y-cable (passive)."""
