// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

(function (root, factory) {
  if (typeof define === 'function' && define.amd) {
    define(['exports', 'kaitai-struct/KaitaiStream', './OsdkControlMode'], factory);
  } else if (typeof exports === 'object' && exports !== null && typeof exports.nodeType !== 'number') {
    factory(exports, require('kaitai-struct/KaitaiStream'), require('./OsdkControlMode'));
  } else {
    factory(root.OsdkMovementControl || (root.OsdkMovementControl = {}), root.KaitaiStream, root.OsdkControlMode || (root.OsdkControlMode = {}));
  }
})(typeof self !== 'undefined' ? self : this, function (OsdkMovementControl_, KaitaiStream, OsdkControlMode_) {
/**
 * The 17-byte value of the movement control command an onboard device sends
 * (in session 0, no ACK) while it holds control authority: a control mode
 * byte and four float32 setpoints whose meaning and units the mode byte
 * selects. Ranges per combination and profile are in rules.yaml
 * (control_modes).
 * @see osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2
 * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md|Source}
 */

var OsdkMovementControl = (function() {
  function OsdkMovementControl(_io, _parent, _root) {
    this._io = _io;
    this._parent = _parent;
    this._root = _root || this;

    this._read();
  }
  OsdkMovementControl.prototype._read = function() {
    this.controlMode = new OsdkControlMode_.OsdkControlMode(this._io, null, null);
    this.x = this._io.readF4le();
    this.y = this._io.readF4le();
    this.z = this._io.readF4le();
    this.yaw = this._io.readF4le();
  }

  /**
   * How the four setpoints are to be interpreted.
   */

  /**
   * Roll angle (deg), x velocity (m/s) or x offset (m), per horizontal logic and frame.
   */

  /**
   * Pitch angle (deg), y velocity (m/s) or y offset (m), per horizontal logic and frame.
   */

  /**
   * Vertical velocity (m/s), height (m) or thrust (%), per vertical logic.
   */

  /**
   * Yaw angle (deg) or yaw rate (deg/s), per yaw logic.
   */

  return OsdkMovementControl;
})();
OsdkMovementControl_.OsdkMovementControl = OsdkMovementControl;
});
