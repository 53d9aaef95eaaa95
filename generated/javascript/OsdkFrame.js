// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

(function (root, factory) {
  if (typeof define === 'function' && define.amd) {
    define(['exports', 'kaitai-struct/KaitaiStream', './OsdkPayload'], factory);
  } else if (typeof exports === 'object' && exports !== null && typeof exports.nodeType !== 'number') {
    factory(exports, require('kaitai-struct/KaitaiStream'), require('./OsdkPayload'));
  } else {
    factory(root.OsdkFrame || (root.OsdkFrame = {}), root.KaitaiStream, root.OsdkPayload || (root.OsdkPayload = {}));
  }
})(typeof self !== 'undefined' ? self : this, function (OsdkFrame_, KaitaiStream, OsdkPayload_) {
/**
 * One frame of the OPEN protocol. A 12-byte header (start byte 0xAA, a u2
 * holding the 10-bit whole-frame length and the 6-bit header version,
 * session/ACK bits, padding/encryption bits, 3 reserved bytes, a sequence
 * number and a CRC-16 over the first 10 bytes) is followed, unless the frame
 * is header-only (LEN = 12), by DATA and a CRC-32 over everything before
 * it. A command frame's DATA starts with command set and id; an ACK frame's
 * DATA is the value alone.
 * 
 * What this description does not check, and a receiver must: both CRCs (the
 * parameters are in rules.yaml, crc), decryption of AES frames (ENC = 1; the
 * data is kept as ciphertext here), and the resynchronising search for the
 * start of a frame in a byte stream (rules.yaml, frame.receiver).
 * LEN 13 to 15 is impossible (a frame with DATA has at least 12 + 0 + 4 bytes
 * and LEN = 16 means an empty DATA with a CRC-32, which is also rejected).
 * @see osdk-conformance shared/reference/PROTOCOL-FACTS.md section 1
 * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_Codec.cpp|Source}
 * @see {@link https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md|Source}
 */

var OsdkFrame = (function() {
  OsdkFrame.CommandSet = Object.freeze({
    ACTIVATION: 0,
    CONTROL: 1,
    PUSH: 2,

    0: "ACTIVATION",
    1: "CONTROL",
    2: "PUSH",
  });

  OsdkFrame.Encryption = Object.freeze({
    PLAIN: 0,
    AES256: 1,

    0: "PLAIN",
    1: "AES256",
  });

  function OsdkFrame(_io, _parent, _root, profile) {
    this._io = _io;
    this._parent = _parent;
    this._root = _root || this;
    this.profile = profile;

    this._read();
  }
  OsdkFrame.prototype._read = function() {
    this.sof = this._io.readBytes(1);
    if (!((KaitaiStream.byteArrayCompare(this.sof, new Uint8Array([170])) == 0))) {
      throw new KaitaiStream.ValidationNotEqualError(new Uint8Array([170]), this.sof, this._io, "/seq/0");
    }
    this.len = this._io.readBitsIntLe(10);
    var _ = this.len;
    if (!( ((_ == 12) || (_ >= 17)) )) {
      throw new KaitaiStream.ValidationExprError(this.len, this._io, "/seq/1");
    }
    this.ver = this._io.readBitsIntLe(6);
    if (!(this.ver == 0)) {
      throw new KaitaiStream.ValidationNotEqualError(0, this.ver, this._io, "/seq/2");
    }
    this.session = this._io.readBitsIntLe(5);
    this.isAck = this._io.readBitsIntLe(1) != 0;
    var _ = this.isAck;
    if (!( ((!(_)) || (this.session != 0)) )) {
      throw new KaitaiStream.ValidationExprError(this.isAck, this._io, "/seq/4");
    }
    this.res0 = this._io.readBitsIntLe(2);
    if (!(this.res0 == 0)) {
      throw new KaitaiStream.ValidationNotEqualError(0, this.res0, this._io, "/seq/5");
    }
    this.padding = this._io.readBitsIntLe(5);
    this.enc = this._io.readBitsIntLe(3);
    var _ = this.enc;
    if (!( (( ((_ == OsdkFrame.Encryption.PLAIN) && (this.padding == 0)) ) || ( ((_ == OsdkFrame.Encryption.AES256) && (this.padding >= 1) && (this.padding <= 16) && (this.len > 16) && (KaitaiStream.mod(this.len - 16, 16) == 0)) )) )) {
      throw new KaitaiStream.ValidationExprError(this.enc, this._io, "/seq/7");
    }
    this.res1 = this._io.readBitsIntLe(24);
    if (!(this.res1 == 0)) {
      throw new KaitaiStream.ValidationNotEqualError(0, this.res1, this._io, "/seq/8");
    }
    this._io.alignToByte();
    this.seq = this._io.readU2le();
    this.crc16 = this._io.readU2le();
    if (this.len > 12) {
      switch (this.enc) {
      case OsdkFrame.Encryption.PLAIN:
        this._raw_data = this._io.readBytes(this.len - 16);
        var _io__raw_data = new KaitaiStream(this._raw_data);
        this.data = new FrameData(_io__raw_data, this, this._root);
        break;
      default:
        this.data = this._io.readBytes(this.len - 16);
        break;
      }
    }
    if (this.len > 12) {
      this.crc32 = this._io.readU4le();
    }
  }

  /**
   * Plain DATA of a command frame (set, id, value) or an ACK frame (value).
   */

  var FrameData = OsdkFrame.FrameData = (function() {
    function FrameData(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    FrameData.prototype._read = function() {
      if (!(this._parent.isAck)) {
        this.cmdSet = this._io.readU1();
      }
      if (!(this._parent.isAck)) {
        this.cmdId = this._io.readU1();
      }
      if (!(this._parent.isAck)) {
        this._raw_value = this._io.readBytesFull();
        var _io__raw_value = new KaitaiStream(this._raw_value);
        this.value = new OsdkPayload_.OsdkPayload(_io__raw_value, null, null, this.cmdSetCode, this.cmdId, false, this._root.profile);
      }
      if (this._parent.isAck) {
        this.ackValue = this._io.readBytesFull();
      }
    }

    /**
     * The command set byte as a number, named by the enum or not.
     */
    Object.defineProperty(FrameData.prototype, 'cmdSetCode', {
      get: function() {
        if (this._m_cmdSetCode !== undefined)
          return this._m_cmdSetCode;
        if (!(this._parent.isAck)) {
          var _pos = this._io.pos;
          this._io.seek(0);
          this._m_cmdSetCode = this._io.readU1();
          this._io.seek(_pos);
        }
        return this._m_cmdSetCode;
      }
    });

    /**
     * Command set.
     */

    /**
     * Command id within the set.
     */

    /**
     * The command's value, typed by set and id.
     */

    /**
     * An ACK's value, raw: only the command it answers (matched by SEQ)
     * says its type; decode it with osdk_payload(set, id, true, profile).
     */

    return FrameData;
  })();

  /**
   * The bytes CRC-16 is computed over.
   */
  Object.defineProperty(OsdkFrame.prototype, 'crc16Covered', {
    get: function() {
      if (this._m_crc16Covered !== undefined)
        return this._m_crc16Covered;
      var _pos = this._io.pos;
      this._io.seek(0);
      this._m_crc16Covered = this._io.readBytes(10);
      this._io.seek(_pos);
      return this._m_crc16Covered;
    }
  });

  /**
   * The bytes CRC-32 is computed over.
   */
  Object.defineProperty(OsdkFrame.prototype, 'crc32Covered', {
    get: function() {
      if (this._m_crc32Covered !== undefined)
        return this._m_crc32Covered;
      if (this.len > 12) {
        var _pos = this._io.pos;
        this._io.seek(0);
        this._m_crc32Covered = this._io.readBytes(this.len - 4);
        this._io.seek(_pos);
      }
      return this._m_crc32Covered;
    }
  });

  /**
   * true for a 12-byte frame with neither DATA nor CRC-32.
   */
  Object.defineProperty(OsdkFrame.prototype, 'headerOnly', {
    get: function() {
      if (this._m_headerOnly !== undefined)
        return this._m_headerOnly;
      this._m_headerOnly = this.len == 12;
      return this._m_headerOnly;
    }
  });

  /**
   * Start of frame.
   */

  /**
   * Length of the whole frame in bytes, header and CRC-32 included.
   */

  /**
   * Header version, always 0.
   */

  /**
   * 0 no ACK wanted; 1 ACK wanted, loss tolerated; 2-31 ACK required.
   */

  /**
   * true for an ACK frame, false for a command frame. A session-0 command
   * wants no ACK, so an ACK never has session 0 (ERRATA E24).
   */

  /**
   * Reserved, 0.
   */

  /**
   * Number of AES padding bytes at the end of DATA (0 when plain).
   */

  /**
   * Encryption of DATA. Plain DATA has no padding; AES DATA is whole
   * 16-byte blocks with 1 to 16 bytes of padding (ERRATA E23).
   */

  /**
   * Reserved, 0.
   */

  /**
   * Sequence number; an ACK repeats the SEQ of its command.
   */

  /**
   * CRC-16 over bytes 0-9 (rules.yaml crc.crc16), little-endian.
   */

  /**
   * DATA; decoded when plain, kept as ciphertext when encrypted.
   */

  /**
   * CRC-32 over every byte before it (rules.yaml crc.crc32), little-endian.
   */

  /**
   * Broadcast wire profile, used to decode flight data frames.
   */

  return OsdkFrame;
})();
OsdkFrame_.OsdkFrame = OsdkFrame;
});
