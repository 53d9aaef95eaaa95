// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

(function (root, factory) {
  if (typeof define === 'function' && define.amd) {
    define(['exports', 'kaitai-struct/KaitaiStream'], factory);
  } else if (typeof exports === 'object' && exports !== null && typeof exports.nodeType !== 'number') {
    factory(exports, require('kaitai-struct/KaitaiStream'));
  } else {
    factory(root.OsdkControlMode || (root.OsdkControlMode = {}), root.KaitaiStream);
  }
})(typeof self !== 'undefined' ? self : this, function (OsdkControlMode_, KaitaiStream) {
/**
 * The control mode byte says how the flight controller interprets the four
 * setpoints of a movement control command: horizontal logic (tilt angle,
 * velocity or position offset), vertical logic (velocity, position or
 * thrust), yaw logic (angle or rate), the horizontal reference frame and
 * the stable-mode flag. Fields are listed from bit 0 upward. Patterns with
 * no enum name (horizontal 3, vertical 3, frame 2 and 3) are undefined in
 * these firmwares; rules.yaml (control_mode) classifies every byte, and the
 * 14 documented combinations with their input ranges are in
 * rules.yaml (control_modes).
 * @see osdk-conformance seed shared/seeds/000_b7658b258220b5c1.txt (Control mode byte)
 * @see osdk-conformance shared/reference/PROTOCOL-FACTS.md section 4
 * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.9.0/osdk-core/api/inc/dji_control.hpp|Source}
 */

var OsdkControlMode = (function() {
  OsdkControlMode.HorizontalFrame = Object.freeze({
    GROUND: 0,
    BODY: 1,

    0: "GROUND",
    1: "BODY",
  });

  OsdkControlMode.HorizontalLogic = Object.freeze({
    HORI_ATTI_TILT_ANG: 0,
    HORI_VEL: 1,
    HORI_POS: 2,

    0: "HORI_ATTI_TILT_ANG",
    1: "HORI_VEL",
    2: "HORI_POS",
  });

  OsdkControlMode.StableMode = Object.freeze({
    NON_STABLE: 0,
    STABLE: 1,

    0: "NON_STABLE",
    1: "STABLE",
  });

  OsdkControlMode.VerticalLogic = Object.freeze({
    VERT_VEL: 0,
    VERT_POS: 1,
    VERT_THRUST: 2,

    0: "VERT_VEL",
    1: "VERT_POS",
    2: "VERT_THRUST",
  });

  OsdkControlMode.YawLogic = Object.freeze({
    YAW_ANG: 0,
    YAW_RATE: 1,

    0: "YAW_ANG",
    1: "YAW_RATE",
  });

  function OsdkControlMode(_io, _parent, _root) {
    this._io = _io;
    this._parent = _parent;
    this._root = _root || this;

    this._read();
  }
  OsdkControlMode.prototype._read = function() {
    this.stableMode = this._io.readBitsIntLe(1);
    this.horizontalFrame = this._io.readBitsIntLe(2);
    this.yawLogic = this._io.readBitsIntLe(1);
    this.verticalLogic = this._io.readBitsIntLe(2);
    this.horizontalLogic = this._io.readBitsIntLe(2);
  }

  /**
   * Bit 0. Stable mode on FW 3.1 profiles; it affects horizontal control
   * only. On m100-fw2.3 the same bit selects the yaw frame (0 ground,
   * 1 body) and must be 0 with yaw angle (ERRATA E15, rules.yaml
   * control_mode.bit0_by_profile).
   */

  /**
   * Bits 2-1. Reference frame of the horizontal setpoints.
   */

  /**
   * Bit 3. Yaw setpoint is an angle (ground frame enforced) or a rate.
   */

  /**
   * Bits 5-4. Meaning of the vertical (throttle) setpoint.
   */

  /**
   * Bits 7-6. Meaning of the two horizontal (roll, pitch) setpoints.
   */

  return OsdkControlMode;
})();
OsdkControlMode_.OsdkControlMode = OsdkControlMode;
});
