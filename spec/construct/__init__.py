"""The OPEN protocol spec written a second time, in Construct.

The .ksy files in spec/ are the source of truth for layout and names; this
package transcribes them independently, with the same field names in the
same order, so that the differential tests (tests/test_kaitai_vs_construct.py)
can hold one against the other, and because Construct can also build: the
conformance kit encodes frames with it. It is a subpackage of the kit,
imported as osdk_conformance._construct (pyproject.toml maps this directory
there; it reads spec/rules.yaml through osdk_conformance.core).

Modules, one per ksy file or concern:
  floats           F32/F64 (bit-exact IEEE values), F32le/F64le fields
  enums            every ksy enum as name -> value
  bitfields        LSB-first bit fields (ksy bit-endian: le) embedded in records
  combinators      when (ksy if:), Call (parametrised ksy types), ExactSize (size:)
  control          control_mode, movement_control, encode_movement_control
  broadcast_items  the broadcast item types
  broadcast        the broadcast payload of each profile (composed as spec/rules.yaml says)
  payload          command/ACK values by set, id, direction and profile
  frame            the frame, parse_frame, build_frame
  compiled         Construct's compiler where it parses as the interpreter does
                   (parse_frame uses it; compiled.parse for any other construct)

At this level every top-level ksy type is exported under its ksy id (one
osdk_broadcast_<profile> per profile of spec/rules.yaml); the parametrised
ones (osdk_payload, osdk_frame) are functions of the ksy params.
"""
from . import broadcast as _broadcast
from .broadcast import for_profile as broadcast_for_profile
from .control import control_mode as osdk_control_mode
from .control import encode_movement_control
from .control import movement_control as osdk_movement_control
from .floats import F32, F64, F32le, F64le, IeeeFloat
from .frame import build_frame, osdk_frame, parse_frame
from .payload import osdk_payload

_BROADCASTS = {f"osdk_broadcast_{name}": _broadcast.for_profile(value) for value, name in _broadcast.NAMES.items()}
globals().update(_BROADCASTS)

__all__ = [
    "osdk_control_mode", "osdk_movement_control",
    *_BROADCASTS, "broadcast_for_profile",
    "osdk_payload", "osdk_frame", "parse_frame", "build_frame", "encode_movement_control",
    "F32", "F64", "F32le", "F64le", "IeeeFloat",
]
