# This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild
# type: ignore

import kaitaistruct
from kaitaistruct import KaitaiStruct, KaitaiStream, BytesIO
from enum import IntEnum


if getattr(kaitaistruct, 'API_VERSION', (0, 9)) < (0, 11):
    raise Exception("Incompatible Kaitai Struct Python API: 0.11 or later is required, but you have %s" % (kaitaistruct.__version__))

class OsdkBroadcastItems(KaitaiStruct):
    """Item types shared by the broadcast profiles. A broadcast payload is a u2
    presence-flag word followed by each present item in flag-bit order; which
    bit carries which item, and which variant of an item (through the params
    below) a profile uses, is decided by the profile's entry in spec/rules.yaml,
    from which the osdk_broadcast_<profile>.ksy files are generated. All structures are packed,
    little-endian; bit fields are numbered from the least significant bit.
    This file has no seq of its own: it only provides types and enums.
    
    .. seealso::
       osdk-conformance seed shared/seeds/000_b7658b258220b5c1.txt (Flight Data table)
    
    
    .. seealso::
       osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3
    
    
    .. seealso::
       Source - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/Appendix.md
    """

    class ControlDevice(IntEnum):
        rc = 0
        mobile_device = 1
        onboard_device = 2

    class CurMovControlMode(IntEnum):
        atti_stop = 0
        horiz_ang_vert_vel_yaw_ang = 1
        horiz_ang_vert_vel_yaw_rate = 2
        horiz_vel_vert_vel_yaw_ang = 3
        horiz_vel_vert_vel_yaw_rate = 4
        horiz_pos_vert_vel_yaw_ang = 5
        horiz_pos_vert_vel_yaw_rate = 6
        horiz_ang_vert_pos_yaw_ang = 7
        horiz_ang_vert_pos_yaw_rate = 8
        horiz_vel_vert_pos_yaw_ang = 9
        horiz_vel_vert_pos_yaw_rate = 10
        horiz_pos_vert_pos_yaw_ang = 11
        horiz_pos_vert_pos_yaw_rate = 12
        horiz_ang_vert_thr_yaw_ang = 13
        horiz_ang_vert_thr_yaw_rate = 14
        horiz_vel_vert_thr_yaw_ang = 15
        horiz_vel_vert_thr_yaw_rate = 16
        horiz_pos_vert_thr_yaw_ang = 17
        horiz_pos_vert_thr_yaw_rate = 18
        gps_atti_ctrl_cl_yaw_rate = 97
        gps_atti_ctrl_yaw_rate = 98
        atti_ctrl_yaw_rate = 99
        atti_ctrl_stop = 100
    def __init__(self, _io, _parent=None, _root=None):
        super(OsdkBroadcastItems, self).__init__(_io)
        self._parent = _parent
        self._root = _root or self
        self._read()

    def _read(self):
        pass


    def _fetch_instances(self):
        pass

    class ControlInfo(KaitaiStruct):
        """Source of control. FW 2.3 sends the device byte alone (1 byte); FW 3.1
        sends the current API control mode first, then the device byte.
        """
        def __init__(self, has_mode, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.ControlInfo, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self.has_mode = has_mode
            self._read()

        def _read(self):
            if self.has_mode:
                pass
                self.cur_mov_control_mode = KaitaiStream.resolve_enum(OsdkBroadcastItems.CurMovControlMode, self._io.read_u1())

            self.control_device = KaitaiStream.resolve_enum(OsdkBroadcastItems.ControlDevice, self._io.read_bits_int_le(3))
            self.onboard_requested = self._io.read_bits_int_le(1) != 0
            self.virtual_rc = self._io.read_bits_int_le(1) != 0
            self.reserved = self._io.read_bits_int_le(3)


        def _fetch_instances(self):
            pass
            if self.has_mode:
                pass



    class Gimbal(KaitaiStruct):
        """Gimbal attitude in degrees. FW 2.3 sends the three angles only
        (12 bytes); FW 3.1 appends a limit byte (13 bytes).
        """
        def __init__(self, has_limit_byte, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.Gimbal, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self.has_limit_byte = has_limit_byte
            self._read()

        def _read(self):
            self.roll = self._io.read_f4le()
            self.pitch = self._io.read_f4le()
            self.yaw = self._io.read_f4le()
            if self.has_limit_byte:
                pass
                self.limit = OsdkBroadcastItems.GimbalLimit(self._io, self, self._root)



        def _fetch_instances(self):
            pass
            if self.has_limit_byte:
                pass
                self.limit._fetch_instances()



    class GimbalLimit(KaitaiStruct):
        """The gimbal limit byte."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.GimbalLimit, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.pitch_limit = self._io.read_bits_int_le(1) != 0
            self.roll_limit = self._io.read_bits_int_le(1) != 0
            self.yaw_limit = self._io.read_bits_int_le(1) != 0
            self.reserved = self._io.read_bits_int_le(5)


        def _fetch_instances(self):
            pass


    class GpsDetail(KaitaiStruct):
        """Detailed GPS information, A3 family only (flag bit 6 in a3-fw3.1)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.GpsDetail, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.date = self._io.read_u4le()
            self.time = self._io.read_u4le()
            self.longitude = self._io.read_s4le()
            self.latitude = self._io.read_s4le()
            self.height_msl = self._io.read_s4le()
            self.vel_n = self._io.read_f4le()
            self.vel_e = self._io.read_f4le()
            self.vel_d = self._io.read_f4le()


        def _fetch_instances(self):
            pass


    class Magnetometer(KaitaiStruct):
        """Raw magnetometer reading, unitless counts."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.Magnetometer, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.x = self._io.read_s2le()
            self.y = self._io.read_s2le()
            self.z = self._io.read_s2le()


        def _fetch_instances(self):
            pass


    class Position(KaitaiStruct):
        """GPS position and altitude (flag bit 5). Latitude comes first on the
        wire although the seed's table lists longitude first (ERRATA E01).
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.Position, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.latitude = self._io.read_f8le()
            self.longitude = self._io.read_f8le()
            self.altitude = self._io.read_f4le()
            self.height = self._io.read_f4le()
            self.gps_health = self._io.read_u1()


        def _fetch_instances(self):
            pass


    class Quaternion(KaitaiStruct):
        """Attitude quaternion from the ground frame to the body frame (flag bit 1)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.Quaternion, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.q0 = self._io.read_f4le()
            self.q1 = self._io.read_f4le()
            self.q2 = self._io.read_f4le()
            self.q3 = self._io.read_f4le()


        def _fetch_instances(self):
            pass


    class Rc(KaitaiStruct):
        """Remote controller sticks and switches. Sticks range -10000..10000;
        mode is -8000 (P), 0 (A) or 8000 (F); gear is -4545 or -10000.
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.Rc, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.roll = self._io.read_s2le()
            self.pitch = self._io.read_s2le()
            self.yaw = self._io.read_s2le()
            self.throttle = self._io.read_s2le()
            self.mode = self._io.read_s2le()
            self.gear = self._io.read_s2le()


        def _fetch_instances(self):
            pass


    class RtkDetail(KaitaiStruct):
        """Detailed RTK information, A3 family only (flag bit 7 in a3-fw3.1)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.RtkDetail, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.date = self._io.read_u4le()
            self.time = self._io.read_u4le()
            self.longitude = self._io.read_f8le()
            self.latitude = self._io.read_f8le()
            self.height_msl = self._io.read_f4le()
            self.vel_n = self._io.read_f4le()
            self.vel_e = self._io.read_f4le()
            self.vel_d = self._io.read_f4le()
            self.yaw = self._io.read_s2le()
            self.position_flag = self._io.read_u1()
            self.yaw_flag = self._io.read_u1()


        def _fetch_instances(self):
            pass


    class TimeStamp(KaitaiStruct):
        """Time stamp item (flag bit 0). FW 2.3 sends only the 4-byte tick
        counter; FW 3.1 adds the nanosecond counter and the sync flag (9 bytes).
        """
        def __init__(self, has_ns_and_sync, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.TimeStamp, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self.has_ns_and_sync = has_ns_and_sync
            self._read()

        def _read(self):
            self.time = self._io.read_u4le()
            if self.has_ns_and_sync:
                pass
                self.nano_time = self._io.read_u4le()

            if self.has_ns_and_sync:
                pass
                self.sync_flag = self._io.read_u1()



        def _fetch_instances(self):
            pass
            if self.has_ns_and_sync:
                pass

            if self.has_ns_and_sync:
                pass



    class Vector3f(KaitaiStruct):
        """Three float32 components. Used for linear acceleration (m/s^2 when
        fused, g when raw) and angular rate (rad/s); which of raw or fusion is
        sent is a setting of the flight controller, not visible on the wire.
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.Vector3f, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.x = self._io.read_f4le()
            self.y = self._io.read_f4le()
            self.z = self._io.read_f4le()


        def _fetch_instances(self):
            pass


    class Velocity(KaitaiStruct):
        """Linear velocity in the ground frame, m/s, with a status byte (flag bit 3)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(OsdkBroadcastItems.Velocity, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.x = self._io.read_f4le()
            self.y = self._io.read_f4le()
            self.z = self._io.read_f4le()
            self.data_valid = self._io.read_bits_int_le(1) != 0
            self.sensor_id = self._io.read_bits_int_le(4)
            self.reserved = self._io.read_bits_int_le(3)


        def _fetch_instances(self):
            pass



