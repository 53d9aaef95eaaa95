"""`osdkc doctor`: what stands between this host and a working OPEN link."""
