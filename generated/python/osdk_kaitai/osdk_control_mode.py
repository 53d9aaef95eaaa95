# This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild
# type: ignore

import kaitaistruct
from kaitaistruct import KaitaiStruct, KaitaiStream, BytesIO
from enum import IntEnum


if getattr(kaitaistruct, 'API_VERSION', (0, 9)) < (0, 11):
    raise Exception("Incompatible Kaitai Struct Python API: 0.11 or later is required, but you have %s" % (kaitaistruct.__version__))

class OsdkControlMode(KaitaiStruct):
    """The control mode byte says how the flight controller interprets the four
    setpoints of a movement control command: horizontal logic (tilt angle,
    velocity or position offset), vertical logic (velocity, position or
    thrust), yaw logic (angle or rate), the horizontal reference frame and
    the stable-mode flag. Fields are listed from bit 0 upward. Patterns with
    no enum name (horizontal 3, vertical 3, frame 2 and 3) are undefined in
    these firmwares; rules.yaml (control_mode) classifies every byte, and the
    14 documented combinations with their input ranges are in
    rules.yaml (control_modes).
    
    .. seealso::
       osdk-conformance seed shared/seeds/000_b7658b258220b5c1.txt (Control mode byte)
    
    
    .. seealso::
       osdk-conformance shared/reference/PROTOCOL-FACTS.md section 4
    
    
    .. seealso::
       Source - https://github.com/dji-sdk/Onboard-SDK/blob/3.9.0/osdk-core/api/inc/dji_control.hpp
    """

    class HorizontalFrame(IntEnum):
        ground = 0
        body = 1

    class HorizontalLogic(IntEnum):
        hori_atti_tilt_ang = 0
        hori_vel = 1
        hori_pos = 2

    class StableMode(IntEnum):
        non_stable = 0
        stable = 1

    class VerticalLogic(IntEnum):
        vert_vel = 0
        vert_pos = 1
        vert_thrust = 2

    class YawLogic(IntEnum):
        yaw_ang = 0
        yaw_rate = 1
    def __init__(self, _io, _parent=None, _root=None):
        super(OsdkControlMode, self).__init__(_io)
        self._parent = _parent
        self._root = _root or self
        self._read()

    def _read(self):
        self.stable_mode = KaitaiStream.resolve_enum(OsdkControlMode.StableMode, self._io.read_bits_int_le(1))
        self.horizontal_frame = KaitaiStream.resolve_enum(OsdkControlMode.HorizontalFrame, self._io.read_bits_int_le(2))
        self.yaw_logic = KaitaiStream.resolve_enum(OsdkControlMode.YawLogic, self._io.read_bits_int_le(1))
        self.vertical_logic = KaitaiStream.resolve_enum(OsdkControlMode.VerticalLogic, self._io.read_bits_int_le(2))
        self.horizontal_logic = KaitaiStream.resolve_enum(OsdkControlMode.HorizontalLogic, self._io.read_bits_int_le(2))


    def _fetch_instances(self):
        pass


