// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

package osdk_kaitai;

import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStruct;
import io.kaitai.struct.KaitaiStream;
import java.io.IOException;
import java.util.Map;
import java.util.HashMap;
import java.util.ArrayList;
import java.util.List;


/**
 * The value carried in a frame's DATA, chosen by command set and id. A
 * command frame names its set and id itself; an ACK frame does not (it
 * repeats the SEQ of the command it answers), so the caller must say which
 * command an ACK belongs to. The broadcast's layout depends on the wire
 * profile of the flight controller, which the caller also supplies.
 * Values of unknown commands are kept as raw bytes. Bytes left over after a
 * known value are an error.
 * @see "osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2"
 * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md">Source</a>
 */
public class OsdkPayload extends KaitaiStruct {

    public enum ActivationResult {
        SUCCESS(0),
        INVALID_PARAMETERS(1),
        CANNOT_RECOGNIZE_ENCRYPTED_PACKAGE(2),
        NEW_APP_ID(3),
        NO_RESPONSE_FROM_APP(4),
        NO_INTERNET(5),
        SERVER_REJECTED(6),
        LEVEL_INSUFFICIENT(7),
        WRONG_SDK_VERSION(8);

        private final long id;
        ActivationResult(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, ActivationResult> byId = new HashMap<Long, ActivationResult>(9);
        static {
            for (ActivationResult e : ActivationResult.values())
                byId.put(e.id(), e);
        }
        public static ActivationResult byId(long id) { return byId.get(id); }
    }

    public enum ControlAck {
        RC_NOT_IN_F_MODE(0),
        RELEASED(1),
        OBTAINED(2),
        OBTAIN_IN_PROGRESS(3),
        RELEASE_IN_PROGRESS(4),
        IN_IOC_MODE(201);

        private final long id;
        ControlAck(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, ControlAck> byId = new HashMap<Long, ControlAck>(6);
        static {
            for (ControlAck e : ControlAck.values())
                byId.put(e.id(), e);
        }
        public static ControlAck byId(long id) { return byId.get(id); }
    }

    public enum ControlRequestCode {
        RELEASE(0),
        OBTAIN(1);

        private final long id;
        ControlRequestCode(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, ControlRequestCode> byId = new HashMap<Long, ControlRequestCode>(2);
        static {
            for (ControlRequestCode e : ControlRequestCode.values())
                byId.put(e.id(), e);
        }
        public static ControlRequestCode byId(long id) { return byId.get(id); }
    }

    public enum FrequencyAck {
        SUCCESS(0),
        PARAMETER_ERROR(1);

        private final long id;
        FrequencyAck(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, FrequencyAck> byId = new HashMap<Long, FrequencyAck>(2);
        static {
            for (FrequencyAck e : FrequencyAck.values())
                byId.put(e.id(), e);
        }
        public static FrequencyAck byId(long id) { return byId.get(id); }
    }

    public enum FrequencyCode {
        HZ_0(0),
        HZ_1(1),
        HZ_10(2),
        HZ_50(3),
        HZ_100(4),
        KEEP(5),
        HZ_200(6),
        HZ_400(7);

        private final long id;
        FrequencyCode(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, FrequencyCode> byId = new HashMap<Long, FrequencyCode>(8);
        static {
            for (FrequencyCode e : FrequencyCode.values())
                byId.put(e.id(), e);
        }
        public static FrequencyCode byId(long id) { return byId.get(id); }
    }

    public enum Profile {
        M100_FW2_3(0),
        M100_FW3_1(1),
        A3_FW3_1(2);

        private final long id;
        Profile(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, Profile> byId = new HashMap<Long, Profile>(3);
        static {
            for (Profile e : Profile.values())
                byId.put(e.id(), e);
        }
        public static Profile byId(long id) { return byId.get(id); }
    }

    public enum VersionAck {
        ACTIVATED(0),
        NOT_ACTIVATED(65281);

        private final long id;
        VersionAck(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, VersionAck> byId = new HashMap<Long, VersionAck>(2);
        static {
            for (VersionAck e : VersionAck.values())
                byId.put(e.id(), e);
        }
        public static VersionAck byId(long id) { return byId.get(id); }
    }

    public OsdkPayload(KaitaiStream _io, int cmdSet, int cmdId, boolean isAck, Profile profile) {
        this(_io, null, null, cmdSet, cmdId, isAck, profile);
    }

    public OsdkPayload(KaitaiStream _io, KaitaiStruct _parent, int cmdSet, int cmdId, boolean isAck, Profile profile) {
        this(_io, _parent, null, cmdSet, cmdId, isAck, profile);
    }

    public OsdkPayload(KaitaiStream _io, KaitaiStruct _parent, OsdkPayload _root, int cmdSet, int cmdId, boolean isAck, Profile profile) {
        super(_io);
        this._parent = _parent;
        this._root = _root == null ? this : _root;
        this.cmdSet = cmdSet;
        this.cmdId = cmdId;
        this.isAck = isAck;
        this.profile = profile;
        _read();
    }
    private void _read() {
        switch (key()) {
        case 0: {
            this.body = new VersionQuery(this._io, this, _root);
            break;
        }
        case 1: {
            this.body = new ActivationRequest(this._io, this, _root);
            break;
        }
        case 16: {
            this.body = new FrequencyRequest(this._io, this, _root);
            break;
        }
        case 256: {
            this.body = new ControlRequest(this._io, this, _root);
            break;
        }
        case 259: {
            this.body = new OsdkMovementControl(this._io);
            break;
        }
        case 512: {
            this.body = new Broadcast(this._io, this, _root, profile());
            break;
        }
        case 513: {
            this.body = new LostControl(this._io, this, _root);
            break;
        }
        case 65536: {
            this.body = new VersionAckValue(this._io, this, _root, profile());
            break;
        }
        case 65537: {
            this.body = new ActivationAckValue(this._io, this, _root);
            break;
        }
        case 65552: {
            this.body = new FrequencyAckValue(this._io, this, _root);
            break;
        }
        case 65792: {
            this.body = new ControlAckValue(this._io, this, _root);
            break;
        }
        case 66049: {
            this.body = new LostControlAckValue(this._io, this, _root);
            break;
        }
        default: {
            this.body = new UnknownValue(this._io, this, _root);
            break;
        }
        }
        this.trailing = this._io.readBytesFull();
        {
            byte[] _it = this.trailing;
            if (!(_it.length == 0)) {
                throw new KaitaiStream.ValidationExprError(this.trailing, this._io, "/seq/1");
            }
        }
    }

    public void _fetchInstances() {
        switch (key()) {
        case 0: {
            ((VersionQuery) (this.body))._fetchInstances();
            break;
        }
        case 1: {
            ((ActivationRequest) (this.body))._fetchInstances();
            break;
        }
        case 16: {
            ((FrequencyRequest) (this.body))._fetchInstances();
            break;
        }
        case 256: {
            ((ControlRequest) (this.body))._fetchInstances();
            break;
        }
        case 259: {
            ((OsdkMovementControl) (this.body))._fetchInstances();
            break;
        }
        case 512: {
            ((Broadcast) (this.body))._fetchInstances();
            break;
        }
        case 513: {
            ((LostControl) (this.body))._fetchInstances();
            break;
        }
        case 65536: {
            ((VersionAckValue) (this.body))._fetchInstances();
            break;
        }
        case 65537: {
            ((ActivationAckValue) (this.body))._fetchInstances();
            break;
        }
        case 65552: {
            ((FrequencyAckValue) (this.body))._fetchInstances();
            break;
        }
        case 65792: {
            ((ControlAckValue) (this.body))._fetchInstances();
            break;
        }
        case 66049: {
            ((LostControlAckValue) (this.body))._fetchInstances();
            break;
        }
        default: {
            ((UnknownValue) (this.body))._fetchInstances();
            break;
        }
        }
    }

    /**
     * ACK of activation.
     */
    public static class ActivationAckValue extends KaitaiStruct {
        public static ActivationAckValue fromFile(String fileName) throws IOException {
            return new ActivationAckValue(new ByteBufferKaitaiStream(fileName));
        }

        public ActivationAckValue(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ActivationAckValue(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public ActivationAckValue(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.ackCode = OsdkPayload.ActivationResult.byId(this._io.readU2le());
        }

        public void _fetchInstances() {
        }
        private ActivationResult ackCode;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Activation result.
         */
        public ActivationResult ackCode() { return ackCode; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * Activation (set 0x00, id 0x01).
     */
    public static class ActivationRequest extends KaitaiStruct {
        public static ActivationRequest fromFile(String fileName) throws IOException {
            return new ActivationRequest(new ByteBufferKaitaiStream(fileName));
        }

        public ActivationRequest(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ActivationRequest(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public ActivationRequest(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.appId = this._io.readU4le();
            this.apiLevel = this._io.readU4le();
            this.sdkVersion = this._io.readU4le();
            this.bundleId = this._io.readBytes(32);
        }

        public void _fetchInstances() {
        }
        private long appId;
        private long apiLevel;
        private long sdkVersion;
        private byte[] bundleId;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Application id issued by DJI.
         */
        public long appId() { return appId; }

        /**
         * API level (reserved in later SDKs).
         */
        public long apiLevel() { return apiLevel; }

        /**
         * SDK version word, e.g. 0x03010A00 (M100) or 0x03016400 (A3).
         */
        public long sdkVersion() { return sdkVersion; }

        /**
         * Bundle id, 32 bytes.
         */
        public byte[] bundleId() { return bundleId; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * Flight data broadcast (set 0x02, id 0x00) in the given profile.
     */
    public static class Broadcast extends KaitaiStruct {

        public Broadcast(KaitaiStream _io, Profile profile) {
            this(_io, null, null, profile);
        }

        public Broadcast(KaitaiStream _io, OsdkPayload _parent, Profile profile) {
            this(_io, _parent, null, profile);
        }

        public Broadcast(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root, Profile profile) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            this.profile = profile;
            _read();
        }
        private void _read() {
            {
                Profile on = profile();
                if (on != null) {
                    switch (profile()) {
                    case A3_FW3_1: {
                        this.data = new OsdkBroadcastA3Fw31(this._io);
                        break;
                    }
                    case M100_FW2_3: {
                        this.data = new OsdkBroadcastM100Fw23(this._io);
                        break;
                    }
                    case M100_FW3_1: {
                        this.data = new OsdkBroadcastM100Fw31(this._io);
                        break;
                    }
                    }
                }
            }
        }

        public void _fetchInstances() {
            {
                Profile on = profile();
                if (on != null) {
                    switch (profile()) {
                    case A3_FW3_1: {
                        ((OsdkBroadcastA3Fw31) (this.data))._fetchInstances();
                        break;
                    }
                    case M100_FW2_3: {
                        ((OsdkBroadcastM100Fw23) (this.data))._fetchInstances();
                        break;
                    }
                    case M100_FW3_1: {
                        ((OsdkBroadcastM100Fw31) (this.data))._fetchInstances();
                        break;
                    }
                    }
                }
            }
        }
        private KaitaiStruct data;
        private Profile profile;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * The broadcast payload.
         */
        public KaitaiStruct data() { return data; }

        /**
         * Wire profile that selects the layout.
         */
        public Profile profile() { return profile; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * ACK of obtain/release control; the first request answers "in progress".
     */
    public static class ControlAckValue extends KaitaiStruct {
        public static ControlAckValue fromFile(String fileName) throws IOException {
            return new ControlAckValue(new ByteBufferKaitaiStream(fileName));
        }

        public ControlAckValue(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ControlAckValue(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public ControlAckValue(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.ackCode = OsdkPayload.ControlAck.byId(this._io.readU2le());
        }

        public void _fetchInstances() {
        }
        private ControlAck ackCode;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Result.
         */
        public ControlAck ackCode() { return ackCode; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * Obtain or release control authority (set 0x01, id 0x00).
     */
    public static class ControlRequest extends KaitaiStruct {
        public static ControlRequest fromFile(String fileName) throws IOException {
            return new ControlRequest(new ByteBufferKaitaiStream(fileName));
        }

        public ControlRequest(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ControlRequest(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public ControlRequest(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.request = OsdkPayload.ControlRequestCode.byId(this._io.readU1());
        }

        public void _fetchInstances() {
        }
        private ControlRequestCode request;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * 1 obtain, 0 release.
         */
        public ControlRequestCode request() { return request; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * ACK of set broadcast frequencies.
     */
    public static class FrequencyAckValue extends KaitaiStruct {
        public static FrequencyAckValue fromFile(String fileName) throws IOException {
            return new FrequencyAckValue(new ByteBufferKaitaiStream(fileName));
        }

        public FrequencyAckValue(KaitaiStream _io) {
            this(_io, null, null);
        }

        public FrequencyAckValue(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public FrequencyAckValue(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.ackCode = OsdkPayload.FrequencyAck.byId(this._io.readU2le());
        }

        public void _fetchInstances() {
        }
        private FrequencyAck ackCode;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Result.
         */
        public FrequencyAck ackCode() { return ackCode; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * Set broadcast frequencies (set 0x00, id 0x10): one frequency code per
     * item in flag-bit order of the profile; tail bytes past the profile's
     * item count are reserved.
     */
    public static class FrequencyRequest extends KaitaiStruct {
        public static FrequencyRequest fromFile(String fileName) throws IOException {
            return new FrequencyRequest(new ByteBufferKaitaiStream(fileName));
        }

        public FrequencyRequest(KaitaiStream _io) {
            this(_io, null, null);
        }

        public FrequencyRequest(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public FrequencyRequest(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.codes = new ArrayList<FrequencyCode>();
            for (int i = 0; i < 16; i++) {
                this.codes.add(OsdkPayload.FrequencyCode.byId(this._io.readU1()));
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.codes.size(); i++) {
            }
        }
        private List<FrequencyCode> codes;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Frequency code for flag bit 0, 1, ... 15.
         */
        public List<FrequencyCode> codes() { return codes; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * Control authority lost, pushed by the flight controller (set 0x02, id 0x01).
     */
    public static class LostControl extends KaitaiStruct {
        public static LostControl fromFile(String fileName) throws IOException {
            return new LostControl(new ByteBufferKaitaiStream(fileName));
        }

        public LostControl(KaitaiStream _io) {
            this(_io, null, null);
        }

        public LostControl(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public LostControl(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.reason = this._io.readU1();
        }

        public void _fetchInstances() {
        }
        private int reason;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Reason code; 0x04 in the documented firmware.
         */
        public int reason() { return reason; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * The device's answer to a lost-control push sent with session > 0.
     */
    public static class LostControlAckValue extends KaitaiStruct {
        public static LostControlAckValue fromFile(String fileName) throws IOException {
            return new LostControlAckValue(new ByteBufferKaitaiStream(fileName));
        }

        public LostControlAckValue(KaitaiStream _io) {
            this(_io, null, null);
        }

        public LostControlAckValue(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public LostControlAckValue(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.ackCode = this._io.readU2le();
        }

        public void _fetchInstances() {
        }
        private int ackCode;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Always 0.
         */
        public int ackCode() { return ackCode; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * Value of a command this spec does not describe, kept raw.
     */
    public static class UnknownValue extends KaitaiStruct {
        public static UnknownValue fromFile(String fileName) throws IOException {
            return new UnknownValue(new ByteBufferKaitaiStream(fileName));
        }

        public UnknownValue(KaitaiStream _io) {
            this(_io, null, null);
        }

        public UnknownValue(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public UnknownValue(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.raw = this._io.readBytesFull();
        }

        public void _fetchInstances() {
        }
        private byte[] raw;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * The value bytes.
         */
        public byte[] raw() { return raw; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * ACK of the version query. FW 3.1 firmware (profiles m100-fw3.1 and
     * a3-fw3.1) puts an 11-byte version ID between the CRC and the name;
     * M100 FW 2.3 has none (ERRATA E30).
     * @see "osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2, "Version reply layout""
     * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_API.cpp">(CoreAPI::getDroneVersionCallback)</a>
     * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.9.0/osdk-core/api/src/dji_vehicle.cpp">(Vehicle::parseDroneVersionInfo)</a>
     * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.2.2/osdk-core/test/DJI_APITest.h">(the names an M100 and an A3 answer)</a>
     */
    public static class VersionAckValue extends KaitaiStruct {

        public VersionAckValue(KaitaiStream _io, Profile profile) {
            this(_io, null, null, profile);
        }

        public VersionAckValue(KaitaiStream _io, OsdkPayload _parent, Profile profile) {
            this(_io, _parent, null, profile);
        }

        public VersionAckValue(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root, Profile profile) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            this.profile = profile;
            _read();
        }
        private void _read() {
            this.ackCode = OsdkPayload.VersionAck.byId(this._io.readU2le());
            this.versionCrc = this._io.readU4le();
            if (hasVersionId()) {
                this.versionId = this._io.readBytes(11);
            }
            this.versionName = this._io.readBytes(32);
        }

        public void _fetchInstances() {
            if (hasVersionId()) {
            }
        }
        private Boolean hasVersionId;

        /**
         * true on FW 3.1 profiles, whose reply carries the 11-byte version ID.
         */
        public Boolean hasVersionId() {
            if (this.hasVersionId != null)
                return this.hasVersionId;
            this.hasVersionId = profile() != OsdkPayload.Profile.M100_FW2_3;
            return this.hasVersionId;
        }
        private VersionAck ackCode;
        private long versionCrc;
        private byte[] versionId;
        private byte[] versionName;
        private Profile profile;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Activation state of the flight controller.
         */
        public VersionAck ackCode() { return ackCode; }

        /**
         * CRC of the firmware version.
         */
        public long versionCrc() { return versionCrc; }

        /**
         * Version ID (FW 3.1 only), decoded raw. Firmware sends 10 ASCII
         * characters and one NUL: the only form that DJI's fixed reader
         * (3.1.x: 11 bytes) and its scanning reader (3.3 to 3.9: up to the
         * first NUL after the code) read alike (ERRATA E30).
         */
        public byte[] versionId() { return versionId; }

        /**
         * Version name, ASCII, NUL-padded, in DJI's form
         * "SDK-v1.0 BETA <hardware>-<a>.<b>.<c>.<d>" (rules.yaml
         * profiles.*.version_ack.version_name); 3.3 to 3.9 hosts read the
         * firmware version from it (ERRATA E30).
         */
        public byte[] versionName() { return versionName; }

        /**
         * Wire profile of the flight controller; it decides whether the version ID is there.
         */
        public Profile profile() { return profile; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }

    /**
     * Get protocol version (set 0x00, id 0x00); the value is one arbitrary byte.
     */
    public static class VersionQuery extends KaitaiStruct {
        public static VersionQuery fromFile(String fileName) throws IOException {
            return new VersionQuery(new ByteBufferKaitaiStream(fileName));
        }

        public VersionQuery(KaitaiStream _io) {
            this(_io, null, null);
        }

        public VersionQuery(KaitaiStream _io, OsdkPayload _parent) {
            this(_io, _parent, null);
        }

        public VersionQuery(KaitaiStream _io, OsdkPayload _parent, OsdkPayload _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.arbitrary = this._io.readU1();
        }

        public void _fetchInstances() {
        }
        private int arbitrary;
        private OsdkPayload _root;
        private OsdkPayload _parent;

        /**
         * Any value; the flight controller ignores it.
         */
        public int arbitrary() { return arbitrary; }
        public OsdkPayload _root() { return _root; }
        public OsdkPayload _parent() { return _parent; }
    }
    private Integer key;

    /**
     * Dispatch key, 0x1SSII for ACKs and 0x0SSII for commands (SS set, II id).
     */
    public Integer key() {
        if (this.key != null)
            return this.key;
        this.key = ((Number) ((((Number) ((isAck() ? 65536 : 0))).longValue() + ((Number) (cmdSet())).longValue() * 256) + ((Number) (cmdId())).longValue())).intValue();
        return this.key;
    }
    private KaitaiStruct body;
    private byte[] trailing;
    private int cmdSet;
    private int cmdId;
    private boolean isAck;
    private Profile profile;
    private OsdkPayload _root;
    private KaitaiStruct _parent;

    /**
     * The value, typed by command and direction.
     */
    public KaitaiStruct body() { return body; }

    /**
     * Bytes after a known value; a conforming value has none.
     */
    public byte[] trailing() { return trailing; }

    /**
     * Command set of the command (or of the command an ACK answers).
     */
    public int cmdSet() { return cmdSet; }

    /**
     * Command id within the set.
     */
    public int cmdId() { return cmdId; }

    /**
     * true when the value is an ACK frame's value.
     */
    public boolean isAck() { return isAck; }

    /**
     * Broadcast wire profile of the flight controller.
     */
    public Profile profile() { return profile; }
    public OsdkPayload _root() { return _root; }
    public KaitaiStruct _parent() { return _parent; }
}
