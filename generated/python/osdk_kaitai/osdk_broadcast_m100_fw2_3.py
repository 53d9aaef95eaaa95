# This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild
# type: ignore

import kaitaistruct
from kaitaistruct import KaitaiStruct, KaitaiStream, BytesIO
from . import osdk_broadcast_items


if getattr(kaitaistruct, 'API_VERSION', (0, 9)) < (0, 11):
    raise Exception("Incompatible Kaitai Struct Python API: 0.11 or later is required, but you have %s" % (kaitaistruct.__version__))

class OsdkBroadcastM100Fw23(KaitaiStruct):
    """Payload of the flight data broadcast (command set 0x02, id 0x00) as sent
    by M100 with firmware 2.3 (OSDK 2.3). A u2 flag word says which items follow; the items follow in
    flag-bit order, each only when its bit is set. This profile uses
    the 4-byte time stamp, the 12-byte gimbal item (no limit byte) and the 1-byte control info item (device byte only).
    A flag word that promises more bytes than the payload holds is an error
    (the DJI SDK reads past the end instead; spec/ERRATA.md E25), and so are set
    reserved flag bits and bytes left over after the last item.
    
    .. seealso::
       osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3 (profile m100-fw2.3)
    
    
    .. seealso::
       Source - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_App.cpp
    """
    def __init__(self, _io, _parent=None, _root=None):
        super(OsdkBroadcastM100Fw23, self).__init__(_io)
        self._parent = _parent
        self._root = _root or self
        self._read()

    def _read(self):
        self.has_time_stamp = self._io.read_bits_int_le(1) != 0
        self.has_quaternion = self._io.read_bits_int_le(1) != 0
        self.has_acceleration = self._io.read_bits_int_le(1) != 0
        self.has_velocity = self._io.read_bits_int_le(1) != 0
        self.has_angular_rate = self._io.read_bits_int_le(1) != 0
        self.has_position = self._io.read_bits_int_le(1) != 0
        self.has_magnetometer = self._io.read_bits_int_le(1) != 0
        self.has_rc = self._io.read_bits_int_le(1) != 0
        self.has_gimbal = self._io.read_bits_int_le(1) != 0
        self.has_flight_status = self._io.read_bits_int_le(1) != 0
        self.has_battery = self._io.read_bits_int_le(1) != 0
        self.has_control_info = self._io.read_bits_int_le(1) != 0
        self.reserved_flags = self._io.read_bits_int_le(4)
        if not self.reserved_flags == 0:
            raise kaitaistruct.ValidationNotEqualError(0, self.reserved_flags, self._io, u"/seq/12")
        if self.has_time_stamp:
            pass
            self.time_stamp = osdk_broadcast_items.OsdkBroadcastItems.TimeStamp(False, self._io)

        if self.has_quaternion:
            pass
            self.quaternion = osdk_broadcast_items.OsdkBroadcastItems.Quaternion(self._io)

        if self.has_acceleration:
            pass
            self.acceleration = osdk_broadcast_items.OsdkBroadcastItems.Vector3f(self._io)

        if self.has_velocity:
            pass
            self.velocity = osdk_broadcast_items.OsdkBroadcastItems.Velocity(self._io)

        if self.has_angular_rate:
            pass
            self.angular_rate = osdk_broadcast_items.OsdkBroadcastItems.Vector3f(self._io)

        if self.has_position:
            pass
            self.position = osdk_broadcast_items.OsdkBroadcastItems.Position(self._io)

        if self.has_magnetometer:
            pass
            self.magnetometer = osdk_broadcast_items.OsdkBroadcastItems.Magnetometer(self._io)

        if self.has_rc:
            pass
            self.rc = osdk_broadcast_items.OsdkBroadcastItems.Rc(self._io)

        if self.has_gimbal:
            pass
            self.gimbal = osdk_broadcast_items.OsdkBroadcastItems.Gimbal(False, self._io)

        if self.has_flight_status:
            pass
            self.flight_status = self._io.read_u1()

        if self.has_battery:
            pass
            self.battery = self._io.read_u1()

        if self.has_control_info:
            pass
            self.control_info = osdk_broadcast_items.OsdkBroadcastItems.ControlInfo(False, self._io)

        self.trailing = self._io.read_bytes_full()
        _ = self.trailing
        if not len(_) == 0:
            raise kaitaistruct.ValidationExprError(self.trailing, self._io, u"/seq/25")


    def _fetch_instances(self):
        pass
        if self.has_time_stamp:
            pass
            self.time_stamp._fetch_instances()

        if self.has_quaternion:
            pass
            self.quaternion._fetch_instances()

        if self.has_acceleration:
            pass
            self.acceleration._fetch_instances()

        if self.has_velocity:
            pass
            self.velocity._fetch_instances()

        if self.has_angular_rate:
            pass
            self.angular_rate._fetch_instances()

        if self.has_position:
            pass
            self.position._fetch_instances()

        if self.has_magnetometer:
            pass
            self.magnetometer._fetch_instances()

        if self.has_rc:
            pass
            self.rc._fetch_instances()

        if self.has_gimbal:
            pass
            self.gimbal._fetch_instances()

        if self.has_flight_status:
            pass

        if self.has_battery:
            pass

        if self.has_control_info:
            pass
            self.control_info._fetch_instances()



