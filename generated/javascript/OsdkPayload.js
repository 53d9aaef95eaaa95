// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

(function (root, factory) {
  if (typeof define === 'function' && define.amd) {
    define(['exports', 'kaitai-struct/KaitaiStream', './OsdkBroadcastM100Fw31', './OsdkBroadcastA3Fw31', './OsdkBroadcastM100Fw23', './OsdkMovementControl'], factory);
  } else if (typeof exports === 'object' && exports !== null && typeof exports.nodeType !== 'number') {
    factory(exports, require('kaitai-struct/KaitaiStream'), require('./OsdkBroadcastM100Fw31'), require('./OsdkBroadcastA3Fw31'), require('./OsdkBroadcastM100Fw23'), require('./OsdkMovementControl'));
  } else {
    factory(root.OsdkPayload || (root.OsdkPayload = {}), root.KaitaiStream, root.OsdkBroadcastM100Fw31 || (root.OsdkBroadcastM100Fw31 = {}), root.OsdkBroadcastA3Fw31 || (root.OsdkBroadcastA3Fw31 = {}), root.OsdkBroadcastM100Fw23 || (root.OsdkBroadcastM100Fw23 = {}), root.OsdkMovementControl || (root.OsdkMovementControl = {}));
  }
})(typeof self !== 'undefined' ? self : this, function (OsdkPayload_, KaitaiStream, OsdkBroadcastM100Fw31_, OsdkBroadcastA3Fw31_, OsdkBroadcastM100Fw23_, OsdkMovementControl_) {
/**
 * The value carried in a frame's DATA, chosen by command set and id. A
 * command frame names its set and id itself; an ACK frame does not (it
 * repeats the SEQ of the command it answers), so the caller must say which
 * command an ACK belongs to. The broadcast's layout depends on the wire
 * profile of the flight controller, which the caller also supplies.
 * Values of unknown commands are kept as raw bytes. Bytes left over after a
 * known value are an error.
 * @see osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2
 * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md|Source}
 */

var OsdkPayload = (function() {
  OsdkPayload.ActivationResult = Object.freeze({
    SUCCESS: 0,
    INVALID_PARAMETERS: 1,
    CANNOT_RECOGNIZE_ENCRYPTED_PACKAGE: 2,
    NEW_APP_ID: 3,
    NO_RESPONSE_FROM_APP: 4,
    NO_INTERNET: 5,
    SERVER_REJECTED: 6,
    LEVEL_INSUFFICIENT: 7,
    WRONG_SDK_VERSION: 8,

    0: "SUCCESS",
    1: "INVALID_PARAMETERS",
    2: "CANNOT_RECOGNIZE_ENCRYPTED_PACKAGE",
    3: "NEW_APP_ID",
    4: "NO_RESPONSE_FROM_APP",
    5: "NO_INTERNET",
    6: "SERVER_REJECTED",
    7: "LEVEL_INSUFFICIENT",
    8: "WRONG_SDK_VERSION",
  });

  OsdkPayload.ControlAck = Object.freeze({
    RC_NOT_IN_F_MODE: 0,
    RELEASED: 1,
    OBTAINED: 2,
    OBTAIN_IN_PROGRESS: 3,
    RELEASE_IN_PROGRESS: 4,
    IN_IOC_MODE: 201,

    0: "RC_NOT_IN_F_MODE",
    1: "RELEASED",
    2: "OBTAINED",
    3: "OBTAIN_IN_PROGRESS",
    4: "RELEASE_IN_PROGRESS",
    201: "IN_IOC_MODE",
  });

  OsdkPayload.ControlRequestCode = Object.freeze({
    RELEASE: 0,
    OBTAIN: 1,

    0: "RELEASE",
    1: "OBTAIN",
  });

  OsdkPayload.FrequencyAck = Object.freeze({
    SUCCESS: 0,
    PARAMETER_ERROR: 1,

    0: "SUCCESS",
    1: "PARAMETER_ERROR",
  });

  OsdkPayload.FrequencyCode = Object.freeze({
    HZ_0: 0,
    HZ_1: 1,
    HZ_10: 2,
    HZ_50: 3,
    HZ_100: 4,
    KEEP: 5,
    HZ_200: 6,
    HZ_400: 7,

    0: "HZ_0",
    1: "HZ_1",
    2: "HZ_10",
    3: "HZ_50",
    4: "HZ_100",
    5: "KEEP",
    6: "HZ_200",
    7: "HZ_400",
  });

  OsdkPayload.Profile = Object.freeze({
    M100_FW2_3: 0,
    M100_FW3_1: 1,
    A3_FW3_1: 2,

    0: "M100_FW2_3",
    1: "M100_FW3_1",
    2: "A3_FW3_1",
  });

  OsdkPayload.VersionAck = Object.freeze({
    ACTIVATED: 0,
    NOT_ACTIVATED: 65281,

    0: "ACTIVATED",
    65281: "NOT_ACTIVATED",
  });

  function OsdkPayload(_io, _parent, _root, cmdSet, cmdId, isAck, profile) {
    this._io = _io;
    this._parent = _parent;
    this._root = _root || this;
    this.cmdSet = cmdSet;
    this.cmdId = cmdId;
    this.isAck = isAck;
    this.profile = profile;

    this._read();
  }
  OsdkPayload.prototype._read = function() {
    switch (this.key) {
    case 0:
      this.body = new VersionQuery(this._io, this, this._root);
      break;
    case 1:
      this.body = new ActivationRequest(this._io, this, this._root);
      break;
    case 16:
      this.body = new FrequencyRequest(this._io, this, this._root);
      break;
    case 256:
      this.body = new ControlRequest(this._io, this, this._root);
      break;
    case 259:
      this.body = new OsdkMovementControl_.OsdkMovementControl(this._io, null, null);
      break;
    case 512:
      this.body = new Broadcast(this._io, this, this._root, this.profile);
      break;
    case 513:
      this.body = new LostControl(this._io, this, this._root);
      break;
    case 65536:
      this.body = new VersionAckValue(this._io, this, this._root, this.profile);
      break;
    case 65537:
      this.body = new ActivationAckValue(this._io, this, this._root);
      break;
    case 65552:
      this.body = new FrequencyAckValue(this._io, this, this._root);
      break;
    case 65792:
      this.body = new ControlAckValue(this._io, this, this._root);
      break;
    case 66049:
      this.body = new LostControlAckValue(this._io, this, this._root);
      break;
    default:
      this.body = new UnknownValue(this._io, this, this._root);
      break;
    }
    this.trailing = this._io.readBytesFull();
    var _ = this.trailing;
    if (!(_.length == 0)) {
      throw new KaitaiStream.ValidationExprError(this.trailing, this._io, "/seq/1");
    }
  }

  /**
   * ACK of activation.
   */

  var ActivationAckValue = OsdkPayload.ActivationAckValue = (function() {
    function ActivationAckValue(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ActivationAckValue.prototype._read = function() {
      this.ackCode = this._io.readU2le();
    }

    /**
     * Activation result.
     */

    return ActivationAckValue;
  })();

  /**
   * Activation (set 0x00, id 0x01).
   */

  var ActivationRequest = OsdkPayload.ActivationRequest = (function() {
    function ActivationRequest(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ActivationRequest.prototype._read = function() {
      this.appId = this._io.readU4le();
      this.apiLevel = this._io.readU4le();
      this.sdkVersion = this._io.readU4le();
      this.bundleId = this._io.readBytes(32);
    }

    /**
     * Application id issued by DJI.
     */

    /**
     * API level (reserved in later SDKs).
     */

    /**
     * SDK version word, e.g. 0x03010A00 (M100) or 0x03016400 (A3).
     */

    /**
     * Bundle id, 32 bytes.
     */

    return ActivationRequest;
  })();

  /**
   * Flight data broadcast (set 0x02, id 0x00) in the given profile.
   */

  var Broadcast = OsdkPayload.Broadcast = (function() {
    function Broadcast(_io, _parent, _root, profile) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;
      this.profile = profile;

      this._read();
    }
    Broadcast.prototype._read = function() {
      switch (this.profile) {
      case OsdkPayload.Profile.A3_FW3_1:
        this.data = new OsdkBroadcastA3Fw31_.OsdkBroadcastA3Fw31(this._io, null, null);
        break;
      case OsdkPayload.Profile.M100_FW2_3:
        this.data = new OsdkBroadcastM100Fw23_.OsdkBroadcastM100Fw23(this._io, null, null);
        break;
      case OsdkPayload.Profile.M100_FW3_1:
        this.data = new OsdkBroadcastM100Fw31_.OsdkBroadcastM100Fw31(this._io, null, null);
        break;
      }
    }

    /**
     * The broadcast payload.
     */

    /**
     * Wire profile that selects the layout.
     */

    return Broadcast;
  })();

  /**
   * ACK of obtain/release control; the first request answers "in progress".
   */

  var ControlAckValue = OsdkPayload.ControlAckValue = (function() {
    function ControlAckValue(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ControlAckValue.prototype._read = function() {
      this.ackCode = this._io.readU2le();
    }

    /**
     * Result.
     */

    return ControlAckValue;
  })();

  /**
   * Obtain or release control authority (set 0x01, id 0x00).
   */

  var ControlRequest = OsdkPayload.ControlRequest = (function() {
    function ControlRequest(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ControlRequest.prototype._read = function() {
      this.request = this._io.readU1();
    }

    /**
     * 1 obtain, 0 release.
     */

    return ControlRequest;
  })();

  /**
   * ACK of set broadcast frequencies.
   */

  var FrequencyAckValue = OsdkPayload.FrequencyAckValue = (function() {
    function FrequencyAckValue(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    FrequencyAckValue.prototype._read = function() {
      this.ackCode = this._io.readU2le();
    }

    /**
     * Result.
     */

    return FrequencyAckValue;
  })();

  /**
   * Set broadcast frequencies (set 0x00, id 0x10): one frequency code per
   * item in flag-bit order of the profile; tail bytes past the profile's
   * item count are reserved.
   */

  var FrequencyRequest = OsdkPayload.FrequencyRequest = (function() {
    function FrequencyRequest(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    FrequencyRequest.prototype._read = function() {
      this.codes = [];
      for (var i = 0; i < 16; i++) {
        this.codes.push(this._io.readU1());
      }
    }

    /**
     * Frequency code for flag bit 0, 1, ... 15.
     */

    return FrequencyRequest;
  })();

  /**
   * Control authority lost, pushed by the flight controller (set 0x02, id 0x01).
   */

  var LostControl = OsdkPayload.LostControl = (function() {
    function LostControl(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    LostControl.prototype._read = function() {
      this.reason = this._io.readU1();
    }

    /**
     * Reason code; 0x04 in the documented firmware.
     */

    return LostControl;
  })();

  /**
   * The device's answer to a lost-control push sent with session > 0.
   */

  var LostControlAckValue = OsdkPayload.LostControlAckValue = (function() {
    function LostControlAckValue(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    LostControlAckValue.prototype._read = function() {
      this.ackCode = this._io.readU2le();
    }

    /**
     * Always 0.
     */

    return LostControlAckValue;
  })();

  /**
   * Value of a command this spec does not describe, kept raw.
   */

  var UnknownValue = OsdkPayload.UnknownValue = (function() {
    function UnknownValue(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    UnknownValue.prototype._read = function() {
      this.raw = this._io.readBytesFull();
    }

    /**
     * The value bytes.
     */

    return UnknownValue;
  })();

  /**
   * ACK of the version query. FW 3.1 firmware (profiles m100-fw3.1 and
   * a3-fw3.1) puts an 11-byte version ID between the CRC and the name;
   * M100 FW 2.3 has none (ERRATA E30).
   * @see osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2, "Version reply layout"
   * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_API.cpp|(CoreAPI::getDroneVersionCallback)}
   * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.9.0/osdk-core/api/src/dji_vehicle.cpp|(Vehicle::parseDroneVersionInfo)}
   * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.2.2/osdk-core/test/DJI_APITest.h|(the names an M100 and an A3 answer)}
   */

  var VersionAckValue = OsdkPayload.VersionAckValue = (function() {
    function VersionAckValue(_io, _parent, _root, profile) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;
      this.profile = profile;

      this._read();
    }
    VersionAckValue.prototype._read = function() {
      this.ackCode = this._io.readU2le();
      this.versionCrc = this._io.readU4le();
      if (this.hasVersionId) {
        this.versionId = this._io.readBytes(11);
      }
      this.versionName = this._io.readBytes(32);
    }

    /**
     * true on FW 3.1 profiles, whose reply carries the 11-byte version ID.
     */
    Object.defineProperty(VersionAckValue.prototype, 'hasVersionId', {
      get: function() {
        if (this._m_hasVersionId !== undefined)
          return this._m_hasVersionId;
        this._m_hasVersionId = this.profile != OsdkPayload.Profile.M100_FW2_3;
        return this._m_hasVersionId;
      }
    });

    /**
     * Activation state of the flight controller.
     */

    /**
     * CRC of the firmware version.
     */

    /**
     * Version ID (FW 3.1 only), decoded raw. Firmware sends 10 ASCII
     * characters and one NUL: the only form that DJI's fixed reader
     * (3.1.x: 11 bytes) and its scanning reader (3.3 to 3.9: up to the
     * first NUL after the code) read alike (ERRATA E30).
     */

    /**
     * Version name, ASCII, NUL-padded, in DJI's form
     * "SDK-v1.0 BETA <hardware>-<a>.<b>.<c>.<d>" (rules.yaml
     * profiles.*.version_ack.version_name); 3.3 to 3.9 hosts read the
     * firmware version from it (ERRATA E30).
     */

    /**
     * Wire profile of the flight controller; it decides whether the version ID is there.
     */

    return VersionAckValue;
  })();

  /**
   * Get protocol version (set 0x00, id 0x00); the value is one arbitrary byte.
   */

  var VersionQuery = OsdkPayload.VersionQuery = (function() {
    function VersionQuery(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    VersionQuery.prototype._read = function() {
      this.arbitrary = this._io.readU1();
    }

    /**
     * Any value; the flight controller ignores it.
     */

    return VersionQuery;
  })();

  /**
   * Dispatch key, 0x1SSII for ACKs and 0x0SSII for commands (SS set, II id).
   */
  Object.defineProperty(OsdkPayload.prototype, 'key', {
    get: function() {
      if (this._m_key !== undefined)
        return this._m_key;
      this._m_key = ((this.isAck ? 65536 : 0) + this.cmdSet * 256) + this.cmdId;
      return this._m_key;
    }
  });

  /**
   * The value, typed by command and direction.
   */

  /**
   * Bytes after a known value; a conforming value has none.
   */

  /**
   * Command set of the command (or of the command an ACK answers).
   */

  /**
   * Command id within the set.
   */

  /**
   * true when the value is an ACK frame's value.
   */

  /**
   * Broadcast wire profile of the flight controller.
   */

  return OsdkPayload;
})();
OsdkPayload_.OsdkPayload = OsdkPayload;
});
