"""DJI's Onboard-SDK itself under test (`osdkc sdk ...`)."""
