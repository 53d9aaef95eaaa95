// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

(function (root, factory) {
  if (typeof define === 'function' && define.amd) {
    define(['exports', 'kaitai-struct/KaitaiStream', './OsdkBroadcastItems'], factory);
  } else if (typeof exports === 'object' && exports !== null && typeof exports.nodeType !== 'number') {
    factory(exports, require('kaitai-struct/KaitaiStream'), require('./OsdkBroadcastItems'));
  } else {
    factory(root.OsdkBroadcastA3Fw31 || (root.OsdkBroadcastA3Fw31 = {}), root.KaitaiStream, root.OsdkBroadcastItems || (root.OsdkBroadcastItems = {}));
  }
})(typeof self !== 'undefined' ? self : this, function (OsdkBroadcastA3Fw31_, KaitaiStream, OsdkBroadcastItems_) {
/**
 * Payload of the flight data broadcast (command set 0x02, id 0x00) as sent
 * by A3, N3 and M600 with firmware 3.1 (OSDK 3.1). A u2 flag word says which items follow; the items follow in
 * flag-bit order, each only when its bit is set. This profile uses
 * the 9-byte time stamp, the GPS and RTK detail items at bits 6 and 7, the 13-byte gimbal item and the 2-byte control info item.
 * A flag word that promises more bytes than the payload holds is an error
 * (the DJI SDK reads past the end instead; spec/ERRATA.md E25), and so are set
 * reserved flag bits and bytes left over after the last item.
 * @see osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3 (profile a3-fw3.1)
 * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_App.cpp|Source}
 */

var OsdkBroadcastA3Fw31 = (function() {
  function OsdkBroadcastA3Fw31(_io, _parent, _root) {
    this._io = _io;
    this._parent = _parent;
    this._root = _root || this;

    this._read();
  }
  OsdkBroadcastA3Fw31.prototype._read = function() {
    this.hasTimeStamp = this._io.readBitsIntLe(1) != 0;
    this.hasQuaternion = this._io.readBitsIntLe(1) != 0;
    this.hasAcceleration = this._io.readBitsIntLe(1) != 0;
    this.hasVelocity = this._io.readBitsIntLe(1) != 0;
    this.hasAngularRate = this._io.readBitsIntLe(1) != 0;
    this.hasPosition = this._io.readBitsIntLe(1) != 0;
    this.hasGpsDetail = this._io.readBitsIntLe(1) != 0;
    this.hasRtkDetail = this._io.readBitsIntLe(1) != 0;
    this.hasMagnetometer = this._io.readBitsIntLe(1) != 0;
    this.hasRc = this._io.readBitsIntLe(1) != 0;
    this.hasGimbal = this._io.readBitsIntLe(1) != 0;
    this.hasFlightStatus = this._io.readBitsIntLe(1) != 0;
    this.hasBattery = this._io.readBitsIntLe(1) != 0;
    this.hasControlInfo = this._io.readBitsIntLe(1) != 0;
    this.reservedFlags = this._io.readBitsIntLe(2);
    if (!(this.reservedFlags == 0)) {
      throw new KaitaiStream.ValidationNotEqualError(0, this.reservedFlags, this._io, "/seq/14");
    }
    this._io.alignToByte();
    if (this.hasTimeStamp) {
      this.timeStamp = new OsdkBroadcastItems_.OsdkBroadcastItems.TimeStamp(this._io, null, null, true);
    }
    if (this.hasQuaternion) {
      this.quaternion = new OsdkBroadcastItems_.OsdkBroadcastItems.Quaternion(this._io, null, null);
    }
    if (this.hasAcceleration) {
      this.acceleration = new OsdkBroadcastItems_.OsdkBroadcastItems.Vector3f(this._io, null, null);
    }
    if (this.hasVelocity) {
      this.velocity = new OsdkBroadcastItems_.OsdkBroadcastItems.Velocity(this._io, null, null);
    }
    if (this.hasAngularRate) {
      this.angularRate = new OsdkBroadcastItems_.OsdkBroadcastItems.Vector3f(this._io, null, null);
    }
    if (this.hasPosition) {
      this.position = new OsdkBroadcastItems_.OsdkBroadcastItems.Position(this._io, null, null);
    }
    if (this.hasGpsDetail) {
      this.gpsDetail = new OsdkBroadcastItems_.OsdkBroadcastItems.GpsDetail(this._io, null, null);
    }
    if (this.hasRtkDetail) {
      this.rtkDetail = new OsdkBroadcastItems_.OsdkBroadcastItems.RtkDetail(this._io, null, null);
    }
    if (this.hasMagnetometer) {
      this.magnetometer = new OsdkBroadcastItems_.OsdkBroadcastItems.Magnetometer(this._io, null, null);
    }
    if (this.hasRc) {
      this.rc = new OsdkBroadcastItems_.OsdkBroadcastItems.Rc(this._io, null, null);
    }
    if (this.hasGimbal) {
      this.gimbal = new OsdkBroadcastItems_.OsdkBroadcastItems.Gimbal(this._io, null, null, true);
    }
    if (this.hasFlightStatus) {
      this.flightStatus = this._io.readU1();
    }
    if (this.hasBattery) {
      this.battery = this._io.readU1();
    }
    if (this.hasControlInfo) {
      this.controlInfo = new OsdkBroadcastItems_.OsdkBroadcastItems.ControlInfo(this._io, null, null, true);
    }
    this.trailing = this._io.readBytesFull();
    var _ = this.trailing;
    if (!(_.length == 0)) {
      throw new KaitaiStream.ValidationExprError(this.trailing, this._io, "/seq/29");
    }
  }

  /**
   * Flag bit 0, the time stamp item is present.
   */

  /**
   * Flag bit 1, the quaternion item is present.
   */

  /**
   * Flag bit 2, the acceleration item is present.
   */

  /**
   * Flag bit 3, the velocity item is present.
   */

  /**
   * Flag bit 4, the angular rate item is present.
   */

  /**
   * Flag bit 5, the position item is present.
   */

  /**
   * Flag bit 6, the gps detail item is present.
   */

  /**
   * Flag bit 7, the rtk detail item is present.
   */

  /**
   * Flag bit 8, the magnetometer item is present.
   */

  /**
   * Flag bit 9, the rc item is present.
   */

  /**
   * Flag bit 10, the gimbal item is present.
   */

  /**
   * Flag bit 11, the flight status item is present.
   */

  /**
   * Flag bit 12, the battery item is present.
   */

  /**
   * Flag bit 13, the control info item is present.
   */

  /**
   * Flag bits 14-15 carry no item in this profile and must be 0.
   */

  /**
   * Time stamp.
   */

  /**
   * Attitude quaternion, ground to body.
   */

  /**
   * Linear acceleration (m/s^2 fused, g raw).
   */

  /**
   * Linear velocity in the ground frame, m/s.
   */

  /**
   * Angular rate, rad/s.
   */

  /**
   * GPS position, altitude, height and GPS health.
   */

  /**
   * Detailed GPS information.
   */

  /**
   * Detailed RTK information.
   */

  /**
   * Magnetometer counts.
   */

  /**
   * Remote controller channels.
   */

  /**
   * Gimbal attitude.
   */

  /**
   * Flight status; old or new enum by aircraft and firmware (rules.yaml flight_status).
   */

  /**
   * Battery capacity, percent (0-100).
   */

  /**
   * Source of control.
   */

  /**
   * Bytes after the last present item; a conforming payload has none.
   */

  return OsdkBroadcastA3Fw31;
})();
OsdkBroadcastA3Fw31_.OsdkBroadcastA3Fw31 = OsdkBroadcastA3Fw31;
});
