"""send: print `NAME HEX` for one frame of each command an onboard
computer sends (generated/README.md, Python section).

    PYTHONPATH=build/site python send.py
"""
import sys

import osdk_kaitai

# (name, session, seq, value) of each frame
FRAMES = (
    ("version_query", 2, 1, osdk_kaitai.encode_version_query(arbitrary=0)),
    ("activation", 2, 2, osdk_kaitai.encode_activation(
        app_id=1000001, api_level=2, sdk_version=0x03016400, bundle_id=b"0123456789abcdef0123456789abcdef")),
    ("set_frequency", 2, 3, osdk_kaitai.encode_set_frequency(codes=[1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 0, 0])),
    ("control_authority", 2, 4, osdk_kaitai.encode_control_authority(request=1)),
    ("movement_control", 0, 0x1234, osdk_kaitai.encode_movement_control(
        control_mode=0x4B, x=1.0, y=-2.0, z=0.5, yaw=30.0)),
)


def main(argv):
    if argv:
        print("usage: send.py (no arguments)", file=sys.stderr)
        return 2
    for name, session, seq, value in FRAMES:
        cmd_set, cmd_id = osdk_kaitai.COMMANDS[name]
        frame = osdk_kaitai.encode_frame(cmd_set, cmd_id, is_ack=False, session=session, seq=seq, value=value)
        print(name, frame.hex())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
