"""`osdkc host`: a reference onboard-computer session, and planted host bugs for testing a tap."""
