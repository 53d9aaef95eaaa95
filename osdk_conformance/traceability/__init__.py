"""The spec's own checks: the seed-to-spec trace and `osdkc spec check`."""
