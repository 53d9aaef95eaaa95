"""The OPEN protocol spec written a second time, in Construct.

The .ksy files in spec/ are the source of truth for layout and names; this
package transcribes them independently, with the same field names in the
same order, so that the differential tests (tests/test_kaitai_vs_construct.py)
can hold one against the other, and because Construct can also build: the
conformance kit encodes frames with it.

Modules, one per ksy file or concern:
  floats           F32/F64 (bit-exact IEEE values), F32le/F64le fields
  enums            every ksy enum as name -> value
  bitfields        LSB-first bit fields (ksy bit-endian: le) embedded in records
  combinators      Call (parametrised ksy types), ExactSize (strict `size:`)
  control          control_mode, movement_control, encode_movement_control
  broadcast_items  the broadcast item types
  broadcast        the three broadcast profiles
  payload          command/ACK values by set, id, direction and profile
  frame            the frame, parse_frame, build_frame
"""
from .broadcast import a3_fw3_1, for_profile as broadcast_for_profile, m100_fw2_3, m100_fw3_1
from .control import control_mode, encode_movement_control, movement_control
from .floats import F32, F64, F32le, F64le, IeeeFloat
from .frame import build_frame, frame, frame_data, header, parse_frame
from .payload import payload

__all__ = [
    "F32", "F64", "F32le", "F64le", "IeeeFloat",
    "control_mode", "movement_control", "encode_movement_control",
    "m100_fw2_3", "m100_fw3_1", "a3_fw3_1", "broadcast_for_profile",
    "payload", "frame", "frame_data", "header", "parse_frame", "build_frame",
]
