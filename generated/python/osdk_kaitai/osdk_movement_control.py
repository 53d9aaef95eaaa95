# This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild
# type: ignore

import kaitaistruct
from kaitaistruct import KaitaiStruct, KaitaiStream, BytesIO
from . import osdk_control_mode


if getattr(kaitaistruct, 'API_VERSION', (0, 9)) < (0, 11):
    raise Exception("Incompatible Kaitai Struct Python API: 0.11 or later is required, but you have %s" % (kaitaistruct.__version__))

class OsdkMovementControl(KaitaiStruct):
    """The 17-byte value of the movement control command an onboard device sends
    (in session 0, no ACK) while it holds control authority: a control mode
    byte and four float32 setpoints whose meaning and units the mode byte
    selects. Ranges per combination and profile are in rules.yaml
    (control_modes).
    
    .. seealso::
       osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2
    
    
    .. seealso::
       Source - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md
    """
    def __init__(self, _io, _parent=None, _root=None):
        super(OsdkMovementControl, self).__init__(_io)
        self._parent = _parent
        self._root = _root or self
        self._read()

    def _read(self):
        self.control_mode = osdk_control_mode.OsdkControlMode(self._io)
        self.x = self._io.read_f4le()
        self.y = self._io.read_f4le()
        self.z = self._io.read_f4le()
        self.yaw = self._io.read_f4le()


    def _fetch_instances(self):
        pass
        self.control_mode._fetch_instances()


