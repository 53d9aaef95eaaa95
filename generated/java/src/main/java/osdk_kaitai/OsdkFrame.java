// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

package osdk_kaitai;

import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStruct;
import io.kaitai.struct.KaitaiStream;
import java.io.IOException;
import java.util.Map;
import java.util.HashMap;
import java.util.Arrays;


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
 * @see "osdk-conformance shared/reference/PROTOCOL-FACTS.md section 1"
 * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_Codec.cpp">Source</a>
 * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md">Source</a>
 */
public class OsdkFrame extends KaitaiStruct {

    public enum CommandSet {
        ACTIVATION(0),
        CONTROL(1),
        PUSH(2);

        private final long id;
        CommandSet(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, CommandSet> byId = new HashMap<Long, CommandSet>(3);
        static {
            for (CommandSet e : CommandSet.values())
                byId.put(e.id(), e);
        }
        public static CommandSet byId(long id) { return byId.get(id); }
    }

    public enum Encryption {
        PLAIN(0),
        AES256(1);

        private final long id;
        Encryption(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, Encryption> byId = new HashMap<Long, Encryption>(2);
        static {
            for (Encryption e : Encryption.values())
                byId.put(e.id(), e);
        }
        public static Encryption byId(long id) { return byId.get(id); }
    }

    public OsdkFrame(KaitaiStream _io, OsdkPayload.Profile profile) {
        this(_io, null, null, profile);
    }

    public OsdkFrame(KaitaiStream _io, KaitaiStruct _parent, OsdkPayload.Profile profile) {
        this(_io, _parent, null, profile);
    }

    public OsdkFrame(KaitaiStream _io, KaitaiStruct _parent, OsdkFrame _root, OsdkPayload.Profile profile) {
        super(_io);
        this._parent = _parent;
        this._root = _root == null ? this : _root;
        this.profile = profile;
        _read();
    }
    private void _read() {
        this.sof = this._io.readBytes(1);
        if (!(Arrays.equals(this.sof, new byte[] { -86 }))) {
            throw new KaitaiStream.ValidationNotEqualError(new byte[] { -86 }, this.sof, this._io, "/seq/0");
        }
        this.len = this._io.readBitsIntLe(10);
        {
            long _it = this.len;
            if (!( ((_it == 12) || (_it >= 17)) )) {
                throw new KaitaiStream.ValidationExprError(this.len, this._io, "/seq/1");
            }
        }
        this.ver = this._io.readBitsIntLe(6);
        if (!(this.ver == 0)) {
            throw new KaitaiStream.ValidationNotEqualError(0, this.ver, this._io, "/seq/2");
        }
        this.session = this._io.readBitsIntLe(5);
        this.isAck = this._io.readBitsIntLe(1) != 0;
        {
            boolean _it = this.isAck;
            if (!( ((!(_it)) || (session() != 0)) )) {
                throw new KaitaiStream.ValidationExprError(this.isAck, this._io, "/seq/4");
            }
        }
        this.res0 = this._io.readBitsIntLe(2);
        if (!(this.res0 == 0)) {
            throw new KaitaiStream.ValidationNotEqualError(0, this.res0, this._io, "/seq/5");
        }
        this.padding = this._io.readBitsIntLe(5);
        this.enc = Encryption.byId(this._io.readBitsIntLe(3));
        {
            Encryption _it = this.enc;
            if (!( (( ((_it == Encryption.PLAIN) && (padding() == 0)) ) || ( ((_it == Encryption.AES256) && (padding() >= 1) && (padding() <= 16) && (len() > 16) && (KaitaiStream.mod(len() - 16, 16) == 0)) )) )) {
                throw new KaitaiStream.ValidationExprError(this.enc, this._io, "/seq/7");
            }
        }
        this.res1 = this._io.readBitsIntLe(24);
        if (!(this.res1 == 0)) {
            throw new KaitaiStream.ValidationNotEqualError(0, this.res1, this._io, "/seq/8");
        }
        this.seq = this._io.readU2le();
        this.crc16 = this._io.readU2le();
        if (len() > 12) {
            {
                Encryption on = enc();
                if (on != null) {
                    switch (enc()) {
                    case PLAIN: {
                        KaitaiStream _io_data = this._io.substream(len() - 16);
                        this.data = new FrameData(_io_data, this, _root);
                        break;
                    }
                    default: {
                        this.data = this._io.readBytes(len() - 16);
                        break;
                    }
                    }
                } else {
                    this.data = this._io.readBytes(len() - 16);
                }
            }
        }
        if (len() > 12) {
            this.crc32 = this._io.readU4le();
        }
    }

    public void _fetchInstances() {
        if (len() > 12) {
            {
                Encryption on = enc();
                if (on != null) {
                    switch (enc()) {
                    case PLAIN: {
                        ((FrameData) (this.data))._fetchInstances();
                        break;
                    }
                    default: {
                        break;
                    }
                    }
                } else {
                }
            }
        }
        if (len() > 12) {
        }
        crc16Covered();
        if (this.crc16Covered != null) {
        }
        crc32Covered();
        if (this.crc32Covered != null) {
        }
    }

    /**
     * Plain DATA of a command frame (set, id, value) or an ACK frame (value).
     */
    public static class FrameData extends KaitaiStruct {
        public static FrameData fromFile(String fileName) throws IOException {
            return new FrameData(new ByteBufferKaitaiStream(fileName));
        }

        public FrameData(KaitaiStream _io) {
            this(_io, null, null);
        }

        public FrameData(KaitaiStream _io, OsdkFrame _parent) {
            this(_io, _parent, null);
        }

        public FrameData(KaitaiStream _io, OsdkFrame _parent, OsdkFrame _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            if (!(_parent().isAck())) {
                this.cmdSet = OsdkFrame.CommandSet.byId(this._io.readU1());
            }
            if (!(_parent().isAck())) {
                this.cmdId = this._io.readU1();
            }
            if (!(_parent().isAck())) {
                this._raw_value = this._io.readBytesFull();
                KaitaiStream _io__raw_value = new ByteBufferKaitaiStream(this._raw_value);
                this.value = new OsdkPayload(_io__raw_value, cmdSetCode(), cmdId(), false, _root().profile());
            }
            if (_parent().isAck()) {
                this.ackValue = this._io.readBytesFull();
            }
        }

        public void _fetchInstances() {
            if (!(_parent().isAck())) {
            }
            if (!(_parent().isAck())) {
            }
            if (!(_parent().isAck())) {
                this.value._fetchInstances();
            }
            if (_parent().isAck()) {
            }
            cmdSetCode();
            if (this.cmdSetCode != null) {
            }
        }
        private Integer cmdSetCode;

        /**
         * The command set byte as a number, named by the enum or not.
         */
        public Integer cmdSetCode() {
            if (this.cmdSetCode != null)
                return this.cmdSetCode;
            if (!(_parent().isAck())) {
                long _pos = this._io.pos();
                this._io.seek(0);
                this.cmdSetCode = this._io.readU1();
                this._io.seek(_pos);
            }
            return this.cmdSetCode;
        }
        private CommandSet cmdSet;
        private Integer cmdId;
        private OsdkPayload value;
        private byte[] ackValue;
        private OsdkFrame _root;
        private OsdkFrame _parent;
        private byte[] _raw_value;

        /**
         * Command set.
         */
        public CommandSet cmdSet() { return cmdSet; }

        /**
         * Command id within the set.
         */
        public Integer cmdId() { return cmdId; }

        /**
         * The command's value, typed by set and id.
         */
        public OsdkPayload value() { return value; }

        /**
         * An ACK's value, raw: only the command it answers (matched by SEQ)
         * says its type; decode it with osdk_payload(set, id, true, profile).
         */
        public byte[] ackValue() { return ackValue; }
        public OsdkFrame _root() { return _root; }
        public OsdkFrame _parent() { return _parent; }
        public byte[] _raw_value() { return _raw_value; }
    }
    private byte[] crc16Covered;

    /**
     * The bytes CRC-16 is computed over.
     */
    public byte[] crc16Covered() {
        if (this.crc16Covered != null)
            return this.crc16Covered;
        long _pos = this._io.pos();
        this._io.seek(0);
        this.crc16Covered = this._io.readBytes(10);
        this._io.seek(_pos);
        return this.crc16Covered;
    }
    private byte[] crc32Covered;

    /**
     * The bytes CRC-32 is computed over.
     */
    public byte[] crc32Covered() {
        if (this.crc32Covered != null)
            return this.crc32Covered;
        if (len() > 12) {
            long _pos = this._io.pos();
            this._io.seek(0);
            this.crc32Covered = this._io.readBytes(len() - 4);
            this._io.seek(_pos);
        }
        return this.crc32Covered;
    }
    private Boolean headerOnly;

    /**
     * true for a 12-byte frame with neither DATA nor CRC-32.
     */
    public Boolean headerOnly() {
        if (this.headerOnly != null)
            return this.headerOnly;
        this.headerOnly = len() == 12;
        return this.headerOnly;
    }
    private byte[] sof;
    private long len;
    private long ver;
    private long session;
    private boolean isAck;
    private long res0;
    private long padding;
    private Encryption enc;
    private long res1;
    private int seq;
    private int crc16;
    private Object data;
    private Long crc32;
    private OsdkPayload.Profile profile;
    private OsdkFrame _root;
    private KaitaiStruct _parent;

    /**
     * Start of frame.
     */
    public byte[] sof() { return sof; }

    /**
     * Length of the whole frame in bytes, header and CRC-32 included.
     */
    public long len() { return len; }

    /**
     * Header version, always 0.
     */
    public long ver() { return ver; }

    /**
     * 0 no ACK wanted; 1 ACK wanted, loss tolerated; 2-31 ACK required.
     */
    public long session() { return session; }

    /**
     * true for an ACK frame, false for a command frame. A session-0 command
     * wants no ACK, so an ACK never has session 0 (ERRATA E24).
     */
    public boolean isAck() { return isAck; }

    /**
     * Reserved, 0.
     */
    public long res0() { return res0; }

    /**
     * Number of AES padding bytes at the end of DATA (0 when plain).
     */
    public long padding() { return padding; }

    /**
     * Encryption of DATA. Plain DATA has no padding; AES DATA is whole
     * 16-byte blocks with 1 to 16 bytes of padding (ERRATA E23).
     */
    public Encryption enc() { return enc; }

    /**
     * Reserved, 0.
     */
    public long res1() { return res1; }

    /**
     * Sequence number; an ACK repeats the SEQ of its command.
     */
    public int seq() { return seq; }

    /**
     * CRC-16 over bytes 0-9 (rules.yaml crc.crc16), little-endian.
     */
    public int crc16() { return crc16; }

    /**
     * DATA; decoded when plain, kept as ciphertext when encrypted.
     */
    public Object data() { return data; }

    /**
     * CRC-32 over every byte before it (rules.yaml crc.crc32), little-endian.
     */
    public Long crc32() { return crc32; }

    /**
     * Broadcast wire profile, used to decode flight data frames.
     */
    public OsdkPayload.Profile profile() { return profile; }
    public OsdkFrame _root() { return _root; }
    public KaitaiStruct _parent() { return _parent; }
}
