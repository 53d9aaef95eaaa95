# This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild
# type: ignore

import kaitaistruct
from kaitaistruct import KaitaiStruct, KaitaiStream, BytesIO
from . import osdk_broadcast_m100_fw3_1
from . import osdk_broadcast_a3_fw3_1
from . import osdk_broadcast_m100_fw2_3
from . import osdk_movement_control
from enum import IntEnum


if getattr(kaitaistruct, 'API_VERSION', (0, 9)) < (0, 11):
    raise Exception("Incompatible Kaitai Struct Python API: 0.11 or later is required, but you have %s" % (kaitaistruct.__version__))

class OsdkPayload(KaitaiStruct):
    """The value carried in a frame's DATA, chosen by command set and id. A
    command frame names its set and id itself; an ACK frame does not (it
    repeats the SEQ of the command it answers), so the caller must say which
    command an ACK belongs to. The broadcast's layout depends on the wire
    profile of the flight controller, which the caller also supplies.
    Values of unknown commands are kept as raw bytes. Bytes left over after a
    known value are an error.
    
    .. seealso::
       osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2
    
    
    .. seealso::
       Source - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md
    """

    class ActivationResult(IntEnum):
        success = 0
        invalid_parameters = 1
        cannot_recognize_encrypted_package = 2
        new_app_id = 3
        no_response_from_app = 4
        no_internet = 5
        server_rejected = 6
        level_insufficient = 7
        wrong_sdk_version = 8

    class ControlAck(IntEnum):
        rc_not_in_f_mode = 0
        released = 1
        obtained = 2
        obtain_in_progress = 3
        release_in_progress = 4
        in_ioc_mode = 201

    class ControlRequestCode(IntEnum):
        release = 0
        obtain = 1

    class FrequencyAck(IntEnum):
        success = 0
        parameter_error = 1

    class FrequencyCode(IntEnum):
        hz_0 = 0
        hz_1 = 1
        hz_10 = 2
        hz_50 = 3
        hz_100 = 4
        keep = 5
        hz_200 = 6
        hz_400 = 7

    class Profile(IntEnum):
        m100_fw2_3 = 0
        m100_fw3_1 = 1
        a3_fw3_1 = 2

    class VersionAck(IntEnum):
        activated = 0
        not_activated = 65281
    def __init__(self, cmd_set, cmd_id, is_ack, profile, _io, _parent=None, _root=None):
        super(OsdkPayload, self).__init__(_io)
        self._parent = _parent
        self._root = _root or self
        self.cmd_set = cmd_set
        self.cmd_id = cmd_id
        self.is_ack = is_ack
        self.profile = profile
        self._read()

    def _read(self):
        _on = self.key
        if _on == 0:
            pass
            self.body = OsdkPayload.VersionQuery(self._io, self, self._root)
        elif _on == 1:
            pass
            self.body = OsdkPayload.ActivationRequest(self._io, self, self._root)
        elif _on == 16:
            pass
            self.body = OsdkPayload.FrequencyRequest(self._io, self, self._root)
        elif _on == 256:
            pass
            self.body = OsdkPayload.ControlRequest(self._io, self, self._root)
        elif _on == 259:
            pass
            self.body = osdk_movement_control.OsdkMovementControl(self._io)
        elif _on == 512:
            pass
            self.body = OsdkPayload.Broadcast(self.profile, self._io, self, self._root)
        elif _on == 513:
            pass
            self.body = OsdkPayload.LostControl(self._io, self, self._root)
        elif _on == 65536:
            pass
            self.body = OsdkPayload.VersionAckValue(self.profile, self._io, self, self._root)
        elif _on == 65537:
            pass
            self.body = OsdkPayload.ActivationAckValue(self._io, self, self._root)
        elif _on == 65552:
            pass
            self.body = OsdkPayload.FrequencyAckValue(self._io, self, self._root)
        elif _on == 65792:
            pass
            self.body = OsdkPayload.ControlAckValue(self._io, self, self._root)
        elif _on == 66049:
            pass
            self.body = OsdkPayload.LostControlAckValue(self._io, self, self._root)
        else:
            pass
            self.body = OsdkPayload.UnknownValue(self._io, self, self._root)
        self.trailing = self._io.read_bytes_full()
        _ = self.trailing
        if not len(_) == 0:
            raise kaitaistruct.ValidationExprError(self.trailing, self._io, u"/seq/1")


    def _fetch_instances(self):
        pass
        _on = self.key
        if _on == 0:
            pass
            self.body._fetch_instances()
        elif _on == 1:
            pass
            self.body._fetch_instances()
        elif _on == 16:
            pass
            self.body._fetch_instances()
        elif _on == 256:
            pass
            self.body._fetch_instances()
        elif _on == 259:
            pass
            self.body._fetch_instances()
        elif _on == 512:
            pass
            self.body._fetch_instances()
        elif _on == 513:
            pass
            self.body._fetch_instances()
        elif _on == 65536:
            pass
            self.body._fetch_instances()
        elif _on == 65537:
            pass
            self.body._fetch_instances()
        elif _on == 65552:
            pass
            self.body._fetch_instances()
        elif _on == 65792:
            pass
            self.body._fetch_instances()
        elif _on == 66049:
            pass
            self.body._fetch_instances()
        else:
            pass
            self.body._fetch_instances()

    class ActivationAckValue(KaitaiStruct):
        """ACK of activation."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.ActivationAckValue, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.ack_code = KaitaiStream.resolve_enum(OsdkPayload.ActivationResult, self._io.read_u2le())


        def _fetch_instances(self):
            pass


    class ActivationRequest(KaitaiStruct):
        """Activation (set 0x00, id 0x01)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.ActivationRequest, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.app_id = self._io.read_u4le()
            self.api_level = self._io.read_u4le()
            self.sdk_version = self._io.read_u4le()
            self.bundle_id = self._io.read_bytes(32)


        def _fetch_instances(self):
            pass


    class Broadcast(KaitaiStruct):
        """Flight data broadcast (set 0x02, id 0x00) in the given profile."""
        def __init__(self, profile, _io, _parent=None, _root=None):
            super(OsdkPayload.Broadcast, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self.profile = profile
            self._read()

        def _read(self):
            _on = self.profile
            if _on == OsdkPayload.Profile.a3_fw3_1:
                pass
                self.data = osdk_broadcast_a3_fw3_1.OsdkBroadcastA3Fw31(self._io)
            elif _on == OsdkPayload.Profile.m100_fw2_3:
                pass
                self.data = osdk_broadcast_m100_fw2_3.OsdkBroadcastM100Fw23(self._io)
            elif _on == OsdkPayload.Profile.m100_fw3_1:
                pass
                self.data = osdk_broadcast_m100_fw3_1.OsdkBroadcastM100Fw31(self._io)


        def _fetch_instances(self):
            pass
            _on = self.profile
            if _on == OsdkPayload.Profile.a3_fw3_1:
                pass
                self.data._fetch_instances()
            elif _on == OsdkPayload.Profile.m100_fw2_3:
                pass
                self.data._fetch_instances()
            elif _on == OsdkPayload.Profile.m100_fw3_1:
                pass
                self.data._fetch_instances()


    class ControlAckValue(KaitaiStruct):
        """ACK of obtain/release control; the first request answers "in progress"."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.ControlAckValue, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.ack_code = KaitaiStream.resolve_enum(OsdkPayload.ControlAck, self._io.read_u2le())


        def _fetch_instances(self):
            pass


    class ControlRequest(KaitaiStruct):
        """Obtain or release control authority (set 0x01, id 0x00)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.ControlRequest, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.request = KaitaiStream.resolve_enum(OsdkPayload.ControlRequestCode, self._io.read_u1())


        def _fetch_instances(self):
            pass


    class FrequencyAckValue(KaitaiStruct):
        """ACK of set broadcast frequencies."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.FrequencyAckValue, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.ack_code = KaitaiStream.resolve_enum(OsdkPayload.FrequencyAck, self._io.read_u2le())


        def _fetch_instances(self):
            pass


    class FrequencyRequest(KaitaiStruct):
        """Set broadcast frequencies (set 0x00, id 0x10): one frequency code per
        item in flag-bit order of the profile; tail bytes past the profile's
        item count are reserved.
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.FrequencyRequest, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.codes = []
            for i in range(16):
                self.codes.append(KaitaiStream.resolve_enum(OsdkPayload.FrequencyCode, self._io.read_u1()))



        def _fetch_instances(self):
            pass
            for i in range(len(self.codes)):
                pass



    class LostControl(KaitaiStruct):
        """Control authority lost, pushed by the flight controller (set 0x02, id 0x01)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.LostControl, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.reason = self._io.read_u1()


        def _fetch_instances(self):
            pass


    class LostControlAckValue(KaitaiStruct):
        """The device's answer to a lost-control push sent with session > 0."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.LostControlAckValue, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.ack_code = self._io.read_u2le()


        def _fetch_instances(self):
            pass


    class UnknownValue(KaitaiStruct):
        """Value of a command this spec does not describe, kept raw."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.UnknownValue, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.raw = self._io.read_bytes_full()


        def _fetch_instances(self):
            pass


    class VersionAckValue(KaitaiStruct):
        """ACK of the version query. FW 3.1 firmware (profiles m100-fw3.1 and
        a3-fw3.1) puts an 11-byte version ID between the CRC and the name;
        M100 FW 2.3 has none (ERRATA E30).
        
        .. seealso::
           osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2, "Version reply layout"
        
        
        .. seealso::
           (CoreAPI::getDroneVersionCallback) - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_API.cpp
        
        
        .. seealso::
           (Vehicle::parseDroneVersionInfo) - https://github.com/dji-sdk/Onboard-SDK/blob/3.9.0/osdk-core/api/src/dji_vehicle.cpp
        
        
        .. seealso::
           (the names an M100 and an A3 answer) - https://github.com/dji-sdk/Onboard-SDK/blob/3.2.2/osdk-core/test/DJI_APITest.h
        """
        def __init__(self, profile, _io, _parent=None, _root=None):
            super(OsdkPayload.VersionAckValue, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self.profile = profile
            self._read()

        def _read(self):
            self.ack_code = KaitaiStream.resolve_enum(OsdkPayload.VersionAck, self._io.read_u2le())
            self.version_crc = self._io.read_u4le()
            if self.has_version_id:
                pass
                self.version_id = self._io.read_bytes(11)

            self.version_name = self._io.read_bytes(32)


        def _fetch_instances(self):
            pass
            if self.has_version_id:
                pass


        @property
        def has_version_id(self):
            """true on FW 3.1 profiles, whose reply carries the 11-byte version ID."""
            if hasattr(self, '_m_has_version_id'):
                return self._m_has_version_id

            self._m_has_version_id = self.profile != OsdkPayload.Profile.m100_fw2_3
            return getattr(self, '_m_has_version_id', None)


    class VersionQuery(KaitaiStruct):
        """Get protocol version (set 0x00, id 0x00); the value is one arbitrary byte."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkPayload.VersionQuery, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.arbitrary = self._io.read_u1()


        def _fetch_instances(self):
            pass


    @property
    def key(self):
        """Dispatch key, 0x1SSII for ACKs and 0x0SSII for commands (SS set, II id)."""
        if hasattr(self, '_m_key'):
            return self._m_key

        self._m_key = ((65536 if self.is_ack else 0) + self.cmd_set * 256) + self.cmd_id
        return getattr(self, '_m_key', None)


