"""receive PROFILE: read OPEN protocol bytes from standard input and print
one line per event (the format: generated/README.md, Python section).

    PYTHONPATH=build/site python receive.py a3-fw3.1 < capture.bin
"""
import sys

import osdk_kaitai


def show(event, profile):
    if event.kind == "garbage":
        return [f"garbage {event.offset} {event.length}"]
    if event.kind == "error":
        return [f"error {event.offset} {event.length} {event.error_class}"]
    try:
        frame = osdk_kaitai.decode_frame(event.raw, profile)
    except osdk_kaitai.OsdkError as e:
        return [f"error {event.offset} {event.length} {e.error_class}"]
    if frame.header_only:
        return [f"empty {event.offset} {frame.seq}"]
    if frame.is_ack:
        return [f"ack {event.offset} {frame.seq}"]
    if frame.enc:
        return [f"encrypted {event.offset} {frame.seq}"]
    lines = [f"frame {event.offset} {frame.seq} {frame.data.cmd_set_code} {frame.data.cmd_id}"]
    bc = osdk_kaitai.broadcast_of(frame)
    if bc is not None:
        for item in osdk_kaitai.BROADCAST_ITEMS[profile]:
            value = getattr(bc, item)
            if value is None:
                lines.append(f"  {item} absent")
            elif item == "battery":
                lines.append(f"  battery {bc.battery}")
            elif item == "time_stamp":
                lines.append(f"  time_stamp {bc.time_stamp.time}")
            else:
                lines.append(f"  {item} present")
    return lines


def main(argv):
    if len(argv) != 1 or argv[0] not in osdk_kaitai.PROFILES:
        print(f"usage: receive.py PROFILE (one of {', '.join(osdk_kaitai.PROFILES)})", file=sys.stderr)
        return 2
    profile = argv[0]
    deframer = osdk_kaitai.Deframer()
    while True:
        chunk = sys.stdin.buffer.read1(4096)
        events = deframer.feed(chunk) if chunk else deframer.finish()
        for event in events:
            print("\n".join(show(event, profile)))
        if not chunk:
            return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
