# This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild
# type: ignore

import kaitaistruct
from kaitaistruct import KaitaiStruct, KaitaiStream, BytesIO
from . import osdk_payload
from enum import IntEnum


if getattr(kaitaistruct, 'API_VERSION', (0, 9)) < (0, 11):
    raise Exception("Incompatible Kaitai Struct Python API: 0.11 or later is required, but you have %s" % (kaitaistruct.__version__))

class OsdkFrame(KaitaiStruct):
    """One frame of the OPEN protocol. A 12-byte header (start byte 0xAA, a u2
    holding the 10-bit whole-frame length and the 6-bit header version,
    session/ACK bits, padding/encryption bits, 3 reserved bytes, a sequence
    number and a CRC-16 over the first 10 bytes) is followed, unless the frame
    is header-only (LEN = 12), by DATA and a CRC-32 over everything before
    it. A command frame's DATA starts with command set and id; an ACK frame's
    DATA is the value alone.
    
    What this description does not check, and a receiver must: both CRCs (the
    parameters are in rules.yaml, crc), decryption of AES frames (ENC = 1; the
    data is kept as ciphertext here), and the resynchronising search for the
    start of a frame in a byte stream (rules.yaml, frame.receiver).
    LEN 13 to 15 is impossible (a frame with DATA has at least 12 + 0 + 4 bytes
    and LEN = 16 means an empty DATA with a CRC-32, which is also rejected).
    
    .. seealso::
       osdk-conformance shared/reference/PROTOCOL-FACTS.md section 1
    
    
    .. seealso::
       Source - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_Codec.cpp
    
    
    .. seealso::
       Source - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md
    """

    class CommandSet(IntEnum):
        activation = 0
        control = 1
        push = 2

    class Encryption(IntEnum):
        plain = 0
        aes256 = 1
    def __init__(self, profile, _io, _parent=None, _root=None):
        super(OsdkFrame, self).__init__(_io)
        self._parent = _parent
        self._root = _root or self
        self.profile = profile
        self._read()

    def _read(self):
        self.sof = self._io.read_bytes(1)
        if not self.sof == b"\xAA":
            raise kaitaistruct.ValidationNotEqualError(b"\xAA", self.sof, self._io, u"/seq/0")
        self.len = self._io.read_bits_int_le(10)
        _ = self.len
        if not  ((_ == 12) or (_ >= 17)) :
            raise kaitaistruct.ValidationExprError(self.len, self._io, u"/seq/1")
        self.ver = self._io.read_bits_int_le(6)
        if not self.ver == 0:
            raise kaitaistruct.ValidationNotEqualError(0, self.ver, self._io, u"/seq/2")
        self.session = self._io.read_bits_int_le(5)
        self.is_ack = self._io.read_bits_int_le(1) != 0
        _ = self.is_ack
        if not  (((not (_))) or (self.session != 0)) :
            raise kaitaistruct.ValidationExprError(self.is_ack, self._io, u"/seq/4")
        self.res0 = self._io.read_bits_int_le(2)
        if not self.res0 == 0:
            raise kaitaistruct.ValidationNotEqualError(0, self.res0, self._io, u"/seq/5")
        self.padding = self._io.read_bits_int_le(5)
        self.enc = KaitaiStream.resolve_enum(OsdkFrame.Encryption, self._io.read_bits_int_le(3))
        _ = self.enc
        if not  (( ((_ == OsdkFrame.Encryption.plain) and (self.padding == 0)) ) or ( ((_ == OsdkFrame.Encryption.aes256) and (self.padding >= 1) and (self.padding <= 16) and (self.len > 16) and ((self.len - 16) % 16 == 0)) )) :
            raise kaitaistruct.ValidationExprError(self.enc, self._io, u"/seq/7")
        self.res1 = self._io.read_bits_int_le(24)
        if not self.res1 == 0:
            raise kaitaistruct.ValidationNotEqualError(0, self.res1, self._io, u"/seq/8")
        self.seq = self._io.read_u2le()
        self.crc16 = self._io.read_u2le()
        if self.len > 12:
            pass
            _on = self.enc
            if _on == OsdkFrame.Encryption.plain:
                pass
                self._raw_data = self._io.read_bytes(self.len - 16)
                _io__raw_data = KaitaiStream(BytesIO(self._raw_data))
                self.data = OsdkFrame.FrameData(_io__raw_data, self, self._root)
            else:
                pass
                self.data = self._io.read_bytes(self.len - 16)

        if self.len > 12:
            pass
            self.crc32 = self._io.read_u4le()



    def _fetch_instances(self):
        pass
        if self.len > 12:
            pass
            _on = self.enc
            if _on == OsdkFrame.Encryption.plain:
                pass
                self.data._fetch_instances()
            else:
                pass

        if self.len > 12:
            pass

        _ = self.crc16_covered
        if hasattr(self, '_m_crc16_covered'):
            pass

        _ = self.crc32_covered
        if hasattr(self, '_m_crc32_covered'):
            pass


    class FrameData(KaitaiStruct):
        """Plain DATA of a command frame (set, id, value) or an ACK frame (value)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkFrame.FrameData, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            if (not (self._parent.is_ack)):
                pass
                self.cmd_set = KaitaiStream.resolve_enum(OsdkFrame.CommandSet, self._io.read_u1())

            if (not (self._parent.is_ack)):
                pass
                self.cmd_id = self._io.read_u1()

            if (not (self._parent.is_ack)):
                pass
                self._raw_value = self._io.read_bytes_full()
                _io__raw_value = KaitaiStream(BytesIO(self._raw_value))
                self.value = osdk_payload.OsdkPayload(self.cmd_set_code, self.cmd_id, False, self._root.profile, _io__raw_value)

            if self._parent.is_ack:
                pass
                self.ack_value = self._io.read_bytes_full()



        def _fetch_instances(self):
            pass
            if (not (self._parent.is_ack)):
                pass

            if (not (self._parent.is_ack)):
                pass

            if (not (self._parent.is_ack)):
                pass
                self.value._fetch_instances()

            if self._parent.is_ack:
                pass

            _ = self.cmd_set_code
            if hasattr(self, '_m_cmd_set_code'):
                pass


        @property
        def cmd_set_code(self):
            """The command set byte as a number, named by the enum or not."""
            if hasattr(self, '_m_cmd_set_code'):
                return self._m_cmd_set_code

            if (not (self._parent.is_ack)):
                pass
                _pos = self._io.pos()
                self._io.seek(0)
                self._m_cmd_set_code = self._io.read_u1()
                self._io.seek(_pos)

            return getattr(self, '_m_cmd_set_code', None)


    @property
    def crc16_covered(self):
        """The bytes CRC-16 is computed over."""
        if hasattr(self, '_m_crc16_covered'):
            return self._m_crc16_covered

        _pos = self._io.pos()
        self._io.seek(0)
        self._m_crc16_covered = self._io.read_bytes(10)
        self._io.seek(_pos)
        return getattr(self, '_m_crc16_covered', None)

    @property
    def crc32_covered(self):
        """The bytes CRC-32 is computed over."""
        if hasattr(self, '_m_crc32_covered'):
            return self._m_crc32_covered

        if self.len > 12:
            pass
            _pos = self._io.pos()
            self._io.seek(0)
            self._m_crc32_covered = self._io.read_bytes(self.len - 4)
            self._io.seek(_pos)

        return getattr(self, '_m_crc32_covered', None)

    @property
    def header_only(self):
        """true for a 12-byte frame with neither DATA nor CRC-32."""
        if hasattr(self, '_m_header_only'):
            return self._m_header_only

        self._m_header_only = self.len == 12
        return getattr(self, '_m_header_only', None)


