// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

(function (root, factory) {
  if (typeof define === 'function' && define.amd) {
    define(['exports', 'kaitai-struct/KaitaiStream'], factory);
  } else if (typeof exports === 'object' && exports !== null && typeof exports.nodeType !== 'number') {
    factory(exports, require('kaitai-struct/KaitaiStream'));
  } else {
    factory(root.OsdkBroadcastItems || (root.OsdkBroadcastItems = {}), root.KaitaiStream);
  }
})(typeof self !== 'undefined' ? self : this, function (OsdkBroadcastItems_, KaitaiStream) {
/**
 * Item types shared by the broadcast profiles. A broadcast payload is a u2
 * presence-flag word followed by each present item in flag-bit order; which
 * bit carries which item, and which variant of an item (through the params
 * below) a profile uses, is decided by the profile's entry in spec/rules.yaml,
 * from which the osdk_broadcast_<profile>.ksy files are generated. All structures are packed,
 * little-endian; bit fields are numbered from the least significant bit.
 * This file has no seq of its own: it only provides types and enums.
 * @see osdk-conformance seed shared/seeds/000_b7658b258220b5c1.txt (Flight Data table)
 * @see osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3
 * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/Appendix.md|Source}
 */

var OsdkBroadcastItems = (function() {
  OsdkBroadcastItems.ControlDevice = Object.freeze({
    RC: 0,
    MOBILE_DEVICE: 1,
    ONBOARD_DEVICE: 2,

    0: "RC",
    1: "MOBILE_DEVICE",
    2: "ONBOARD_DEVICE",
  });

  OsdkBroadcastItems.CurMovControlMode = Object.freeze({
    ATTI_STOP: 0,
    HORIZ_ANG_VERT_VEL_YAW_ANG: 1,
    HORIZ_ANG_VERT_VEL_YAW_RATE: 2,
    HORIZ_VEL_VERT_VEL_YAW_ANG: 3,
    HORIZ_VEL_VERT_VEL_YAW_RATE: 4,
    HORIZ_POS_VERT_VEL_YAW_ANG: 5,
    HORIZ_POS_VERT_VEL_YAW_RATE: 6,
    HORIZ_ANG_VERT_POS_YAW_ANG: 7,
    HORIZ_ANG_VERT_POS_YAW_RATE: 8,
    HORIZ_VEL_VERT_POS_YAW_ANG: 9,
    HORIZ_VEL_VERT_POS_YAW_RATE: 10,
    HORIZ_POS_VERT_POS_YAW_ANG: 11,
    HORIZ_POS_VERT_POS_YAW_RATE: 12,
    HORIZ_ANG_VERT_THR_YAW_ANG: 13,
    HORIZ_ANG_VERT_THR_YAW_RATE: 14,
    HORIZ_VEL_VERT_THR_YAW_ANG: 15,
    HORIZ_VEL_VERT_THR_YAW_RATE: 16,
    HORIZ_POS_VERT_THR_YAW_ANG: 17,
    HORIZ_POS_VERT_THR_YAW_RATE: 18,
    GPS_ATTI_CTRL_CL_YAW_RATE: 97,
    GPS_ATTI_CTRL_YAW_RATE: 98,
    ATTI_CTRL_YAW_RATE: 99,
    ATTI_CTRL_STOP: 100,

    0: "ATTI_STOP",
    1: "HORIZ_ANG_VERT_VEL_YAW_ANG",
    2: "HORIZ_ANG_VERT_VEL_YAW_RATE",
    3: "HORIZ_VEL_VERT_VEL_YAW_ANG",
    4: "HORIZ_VEL_VERT_VEL_YAW_RATE",
    5: "HORIZ_POS_VERT_VEL_YAW_ANG",
    6: "HORIZ_POS_VERT_VEL_YAW_RATE",
    7: "HORIZ_ANG_VERT_POS_YAW_ANG",
    8: "HORIZ_ANG_VERT_POS_YAW_RATE",
    9: "HORIZ_VEL_VERT_POS_YAW_ANG",
    10: "HORIZ_VEL_VERT_POS_YAW_RATE",
    11: "HORIZ_POS_VERT_POS_YAW_ANG",
    12: "HORIZ_POS_VERT_POS_YAW_RATE",
    13: "HORIZ_ANG_VERT_THR_YAW_ANG",
    14: "HORIZ_ANG_VERT_THR_YAW_RATE",
    15: "HORIZ_VEL_VERT_THR_YAW_ANG",
    16: "HORIZ_VEL_VERT_THR_YAW_RATE",
    17: "HORIZ_POS_VERT_THR_YAW_ANG",
    18: "HORIZ_POS_VERT_THR_YAW_RATE",
    97: "GPS_ATTI_CTRL_CL_YAW_RATE",
    98: "GPS_ATTI_CTRL_YAW_RATE",
    99: "ATTI_CTRL_YAW_RATE",
    100: "ATTI_CTRL_STOP",
  });

  function OsdkBroadcastItems(_io, _parent, _root) {
    this._io = _io;
    this._parent = _parent;
    this._root = _root || this;

    this._read();
  }
  OsdkBroadcastItems.prototype._read = function() {
  }

  /**
   * Source of control. FW 2.3 sends the device byte alone (1 byte); FW 3.1
   * sends the current API control mode first, then the device byte.
   */

  var ControlInfo = OsdkBroadcastItems.ControlInfo = (function() {
    function ControlInfo(_io, _parent, _root, hasMode) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;
      this.hasMode = hasMode;

      this._read();
    }
    ControlInfo.prototype._read = function() {
      if (this.hasMode) {
        this.curMovControlMode = this._io.readU1();
      }
      this.controlDevice = this._io.readBitsIntLe(3);
      this.onboardRequested = this._io.readBitsIntLe(1) != 0;
      this.virtualRc = this._io.readBitsIntLe(1) != 0;
      this.reserved = this._io.readBitsIntLe(3);
    }

    /**
     * Movement control mode the flight controller is executing (FW 3.1 only).
     */

    /**
     * Device byte bits 0-2, who is in control.
     */

    /**
     * Device byte bit 3, the onboard device has requested control.
     */

    /**
     * Device byte bit 4, virtual RC is enabled.
     */

    /**
     * Device byte bits 5-7, reserved; a receiver ignores them.
     */

    /**
     * true for the 2-byte FW 3.1 form
     */

    return ControlInfo;
  })();

  /**
   * Gimbal attitude in degrees. FW 2.3 sends the three angles only
   * (12 bytes); FW 3.1 appends a limit byte (13 bytes).
   */

  var Gimbal = OsdkBroadcastItems.Gimbal = (function() {
    function Gimbal(_io, _parent, _root, hasLimitByte) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;
      this.hasLimitByte = hasLimitByte;

      this._read();
    }
    Gimbal.prototype._read = function() {
      this.roll = this._io.readF4le();
      this.pitch = this._io.readF4le();
      this.yaw = this._io.readF4le();
      if (this.hasLimitByte) {
        this.limit = new GimbalLimit(this._io, this, this._root);
      }
    }

    /**
     * Gimbal roll, degrees.
     */

    /**
     * Gimbal pitch, degrees.
     */

    /**
     * Gimbal yaw, degrees.
     */

    /**
     * Which axes are at their mechanical limit (FW 3.1 only).
     */

    /**
     * true for the 13-byte FW 3.1 form
     */

    return Gimbal;
  })();

  /**
   * The gimbal limit byte.
   */

  var GimbalLimit = OsdkBroadcastItems.GimbalLimit = (function() {
    function GimbalLimit(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    GimbalLimit.prototype._read = function() {
      this.pitchLimit = this._io.readBitsIntLe(1) != 0;
      this.rollLimit = this._io.readBitsIntLe(1) != 0;
      this.yawLimit = this._io.readBitsIntLe(1) != 0;
      this.reserved = this._io.readBitsIntLe(5);
    }

    /**
     * Bit 0, pitch at its limit.
     */

    /**
     * Bit 1, roll at its limit.
     */

    /**
     * Bit 2, yaw at its limit.
     */

    /**
     * Bits 3-7, reserved; a receiver ignores them.
     */

    return GimbalLimit;
  })();

  /**
   * Detailed GPS information, A3 family only (flag bit 6 in a3-fw3.1).
   */

  var GpsDetail = OsdkBroadcastItems.GpsDetail = (function() {
    function GpsDetail(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    GpsDetail.prototype._read = function() {
      this.date = this._io.readU4le();
      this.time = this._io.readU4le();
      this.longitude = this._io.readS4le();
      this.latitude = this._io.readS4le();
      this.heightMsl = this._io.readS4le();
      this.velN = this._io.readF4le();
      this.velE = this._io.readF4le();
      this.velD = this._io.readF4le();
    }

    /**
     * UTC date as the decimal number yyyymmdd.
     */

    /**
     * UTC time as the decimal number hhmmss.
     */

    /**
     * Longitude, degrees times 1e7. Longitude comes first in this item.
     */

    /**
     * Latitude, degrees times 1e7.
     */

    /**
     * Height above mean sea level, mm.
     */

    /**
     * Velocity towards north, cm/s.
     */

    /**
     * Velocity towards east, cm/s.
     */

    /**
     * Velocity downwards, cm/s.
     */

    return GpsDetail;
  })();

  /**
   * Raw magnetometer reading, unitless counts.
   */

  var Magnetometer = OsdkBroadcastItems.Magnetometer = (function() {
    function Magnetometer(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    Magnetometer.prototype._read = function() {
      this.x = this._io.readS2le();
      this.y = this._io.readS2le();
      this.z = this._io.readS2le();
    }

    /**
     * x axis.
     */

    /**
     * y axis.
     */

    /**
     * z axis.
     */

    return Magnetometer;
  })();

  /**
   * GPS position and altitude (flag bit 5). Latitude comes first on the
   * wire although the seed's table lists longitude first (ERRATA E01).
   */

  var Position = OsdkBroadcastItems.Position = (function() {
    function Position(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    Position.prototype._read = function() {
      this.latitude = this._io.readF8le();
      this.longitude = this._io.readF8le();
      this.altitude = this._io.readF4le();
      this.height = this._io.readF4le();
      this.gpsHealth = this._io.readU1();
    }

    /**
     * Latitude, radians.
     */

    /**
     * Longitude, radians.
     */

    /**
     * Altitude (barometer and IMU when fused, barometer when raw), m.
     */

    /**
     * Height above ground (fusion with ultrasound when below 3 m), m.
     */

    /**
     * GPS health, 0 (no fix) to 5 (best).
     */

    return Position;
  })();

  /**
   * Attitude quaternion from the ground frame to the body frame (flag bit 1).
   */

  var Quaternion = OsdkBroadcastItems.Quaternion = (function() {
    function Quaternion(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    Quaternion.prototype._read = function() {
      this.q0 = this._io.readF4le();
      this.q1 = this._io.readF4le();
      this.q2 = this._io.readF4le();
      this.q3 = this._io.readF4le();
    }

    /**
     * Scalar part.
     */

    /**
     * Vector part, x.
     */

    /**
     * Vector part, y.
     */

    /**
     * Vector part, z.
     */

    return Quaternion;
  })();

  /**
   * Remote controller sticks and switches. Sticks range -10000..10000;
   * mode is -8000 (P), 0 (A) or 8000 (F); gear is -4545 or -10000.
   */

  var Rc = OsdkBroadcastItems.Rc = (function() {
    function Rc(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    Rc.prototype._read = function() {
      this.roll = this._io.readS2le();
      this.pitch = this._io.readS2le();
      this.yaw = this._io.readS2le();
      this.throttle = this._io.readS2le();
      this.mode = this._io.readS2le();
      this.gear = this._io.readS2le();
    }

    /**
     * Roll stick, -10000 (left) to 10000 (right).
     */

    /**
     * Pitch stick, -10000 (down) to 10000 (up).
     */

    /**
     * Yaw stick, -10000 (left) to 10000 (right).
     */

    /**
     * Throttle stick, -10000 (down) to 10000 (up).
     */

    /**
     * Flight mode switch, -8000 P, 0 A, 8000 F.
     */

    /**
     * Gear switch, -4545 or -10000 (see rules.yaml rc_channels).
     */

    return Rc;
  })();

  /**
   * Detailed RTK information, A3 family only (flag bit 7 in a3-fw3.1).
   */

  var RtkDetail = OsdkBroadcastItems.RtkDetail = (function() {
    function RtkDetail(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    RtkDetail.prototype._read = function() {
      this.date = this._io.readU4le();
      this.time = this._io.readU4le();
      this.longitude = this._io.readF8le();
      this.latitude = this._io.readF8le();
      this.heightMsl = this._io.readF4le();
      this.velN = this._io.readF4le();
      this.velE = this._io.readF4le();
      this.velD = this._io.readF4le();
      this.yaw = this._io.readS2le();
      this.positionFlag = this._io.readU1();
      this.yawFlag = this._io.readU1();
    }

    /**
     * UTC date as the decimal number yyyymmdd.
     */

    /**
     * UTC time as the decimal number hhmmss.
     */

    /**
     * Longitude by RTK, degrees.
     */

    /**
     * Latitude by RTK, degrees.
     */

    /**
     * Height above mean sea level by RTK, m.
     */

    /**
     * Velocity towards north, cm/s.
     */

    /**
     * Velocity towards east, cm/s.
     */

    /**
     * Velocity downwards, cm/s.
     */

    /**
     * Angle between the antenna baseline and south, degrees.
     */

    /**
     * RTK positioning solution flag.
     */

    /**
     * RTK heading solution flag.
     */

    return RtkDetail;
  })();

  /**
   * Time stamp item (flag bit 0). FW 2.3 sends only the 4-byte tick
   * counter; FW 3.1 adds the nanosecond counter and the sync flag (9 bytes).
   */

  var TimeStamp = OsdkBroadcastItems.TimeStamp = (function() {
    function TimeStamp(_io, _parent, _root, hasNsAndSync) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;
      this.hasNsAndSync = hasNsAndSync;

      this._read();
    }
    TimeStamp.prototype._read = function() {
      this.time = this._io.readU4le();
      if (this.hasNsAndSync) {
        this.nanoTime = this._io.readU4le();
      }
      if (this.hasNsAndSync) {
        this.syncFlag = this._io.readU1();
      }
    }

    /**
     * Free-running time stamp, in ticks of 1/400 s.
     */

    /**
     * Time stamp in nanoseconds (FW 3.1 only).
     */

    /**
     * Hardware sync signal flag (FW 3.1 only).
     */

    /**
     * true for the 9-byte FW 3.1 form, false for the 4-byte FW 2.3 form
     */

    return TimeStamp;
  })();

  /**
   * Three float32 components. Used for linear acceleration (m/s^2 when
   * fused, g when raw) and angular rate (rad/s); which of raw or fusion is
   * sent is a setting of the flight controller, not visible on the wire.
   */

  var Vector3f = OsdkBroadcastItems.Vector3f = (function() {
    function Vector3f(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    Vector3f.prototype._read = function() {
      this.x = this._io.readF4le();
      this.y = this._io.readF4le();
      this.z = this._io.readF4le();
    }

    /**
     * x component.
     */

    /**
     * y component.
     */

    /**
     * z component.
     */

    return Vector3f;
  })();

  /**
   * Linear velocity in the ground frame, m/s, with a status byte (flag bit 3).
   */

  var Velocity = OsdkBroadcastItems.Velocity = (function() {
    function Velocity(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    Velocity.prototype._read = function() {
      this.x = this._io.readF4le();
      this.y = this._io.readF4le();
      this.z = this._io.readF4le();
      this.dataValid = this._io.readBitsIntLe(1) != 0;
      this.sensorId = this._io.readBitsIntLe(4);
      this.reserved = this._io.readBitsIntLe(3);
    }

    /**
     * Velocity along ground-frame x, m/s.
     */

    /**
     * Velocity along ground-frame y, m/s.
     */

    /**
     * Velocity along ground-frame z, m/s.
     */

    /**
     * Status bit 0, true when the velocity is valid.
     */

    /**
     * Status bits 1-4. The seed calls them reserved; the M100 SDK struct
     * names them the sensor id (ERRATA E04). Informative only.
     */

    /**
     * Status bits 5-7, reserved; a receiver ignores them.
     */

    return Velocity;
  })();

  return OsdkBroadcastItems;
})();
OsdkBroadcastItems_.OsdkBroadcastItems = OsdkBroadcastItems;
});
