// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

package osdk_kaitai;

import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStruct;
import io.kaitai.struct.KaitaiStream;
import java.io.IOException;
import java.util.Map;
import java.util.HashMap;


/**
 * Item types shared by the broadcast profiles. A broadcast payload is a u2
 * presence-flag word followed by each present item in flag-bit order; which
 * bit carries which item, and which variant of an item (through the params
 * below) a profile uses, is decided by the profile's entry in spec/rules.yaml,
 * from which the osdk_broadcast_<profile>.ksy files are generated. All structures are packed,
 * little-endian; bit fields are numbered from the least significant bit.
 * This file has no seq of its own: it only provides types and enums.
 * @see "osdk-conformance seed shared/seeds/000_b7658b258220b5c1.txt (Flight Data table)"
 * @see "osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3"
 * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/Appendix.md">Source</a>
 */
public class OsdkBroadcastItems extends KaitaiStruct {
    public static OsdkBroadcastItems fromFile(String fileName) throws IOException {
        return new OsdkBroadcastItems(new ByteBufferKaitaiStream(fileName));
    }

    public enum ControlDevice {
        RC(0),
        MOBILE_DEVICE(1),
        ONBOARD_DEVICE(2);

        private final long id;
        ControlDevice(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, ControlDevice> byId = new HashMap<Long, ControlDevice>(3);
        static {
            for (ControlDevice e : ControlDevice.values())
                byId.put(e.id(), e);
        }
        public static ControlDevice byId(long id) { return byId.get(id); }
    }

    public enum CurMovControlMode {
        ATTI_STOP(0),
        HORIZ_ANG_VERT_VEL_YAW_ANG(1),
        HORIZ_ANG_VERT_VEL_YAW_RATE(2),
        HORIZ_VEL_VERT_VEL_YAW_ANG(3),
        HORIZ_VEL_VERT_VEL_YAW_RATE(4),
        HORIZ_POS_VERT_VEL_YAW_ANG(5),
        HORIZ_POS_VERT_VEL_YAW_RATE(6),
        HORIZ_ANG_VERT_POS_YAW_ANG(7),
        HORIZ_ANG_VERT_POS_YAW_RATE(8),
        HORIZ_VEL_VERT_POS_YAW_ANG(9),
        HORIZ_VEL_VERT_POS_YAW_RATE(10),
        HORIZ_POS_VERT_POS_YAW_ANG(11),
        HORIZ_POS_VERT_POS_YAW_RATE(12),
        HORIZ_ANG_VERT_THR_YAW_ANG(13),
        HORIZ_ANG_VERT_THR_YAW_RATE(14),
        HORIZ_VEL_VERT_THR_YAW_ANG(15),
        HORIZ_VEL_VERT_THR_YAW_RATE(16),
        HORIZ_POS_VERT_THR_YAW_ANG(17),
        HORIZ_POS_VERT_THR_YAW_RATE(18),
        GPS_ATTI_CTRL_CL_YAW_RATE(97),
        GPS_ATTI_CTRL_YAW_RATE(98),
        ATTI_CTRL_YAW_RATE(99),
        ATTI_CTRL_STOP(100);

        private final long id;
        CurMovControlMode(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, CurMovControlMode> byId = new HashMap<Long, CurMovControlMode>(23);
        static {
            for (CurMovControlMode e : CurMovControlMode.values())
                byId.put(e.id(), e);
        }
        public static CurMovControlMode byId(long id) { return byId.get(id); }
    }

    public OsdkBroadcastItems(KaitaiStream _io) {
        this(_io, null, null);
    }

    public OsdkBroadcastItems(KaitaiStream _io, KaitaiStruct _parent) {
        this(_io, _parent, null);
    }

    public OsdkBroadcastItems(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
        super(_io);
        this._parent = _parent;
        this._root = _root == null ? this : _root;
        _read();
    }
    private void _read() {
    }

    public void _fetchInstances() {
    }

    /**
     * Source of control. FW 2.3 sends the device byte alone (1 byte); FW 3.1
     * sends the current API control mode first, then the device byte.
     */
    public static class ControlInfo extends KaitaiStruct {

        public ControlInfo(KaitaiStream _io, boolean hasMode) {
            this(_io, null, null, hasMode);
        }

        public ControlInfo(KaitaiStream _io, KaitaiStruct _parent, boolean hasMode) {
            this(_io, _parent, null, hasMode);
        }

        public ControlInfo(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root, boolean hasMode) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            this.hasMode = hasMode;
            _read();
        }
        private void _read() {
            if (hasMode()) {
                this.curMovControlMode = OsdkBroadcastItems.CurMovControlMode.byId(this._io.readU1());
            }
            this.controlDevice = OsdkBroadcastItems.ControlDevice.byId(this._io.readBitsIntLe(3));
            this.onboardRequested = this._io.readBitsIntLe(1) != 0;
            this.virtualRc = this._io.readBitsIntLe(1) != 0;
            this.reserved = this._io.readBitsIntLe(3);
        }

        public void _fetchInstances() {
            if (hasMode()) {
            }
        }
        private CurMovControlMode curMovControlMode;
        private ControlDevice controlDevice;
        private boolean onboardRequested;
        private boolean virtualRc;
        private long reserved;
        private boolean hasMode;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * Movement control mode the flight controller is executing (FW 3.1 only).
         */
        public CurMovControlMode curMovControlMode() { return curMovControlMode; }

        /**
         * Device byte bits 0-2, who is in control.
         */
        public ControlDevice controlDevice() { return controlDevice; }

        /**
         * Device byte bit 3, the onboard device has requested control.
         */
        public boolean onboardRequested() { return onboardRequested; }

        /**
         * Device byte bit 4, virtual RC is enabled.
         */
        public boolean virtualRc() { return virtualRc; }

        /**
         * Device byte bits 5-7, reserved; a receiver ignores them.
         */
        public long reserved() { return reserved; }

        /**
         * true for the 2-byte FW 3.1 form
         */
        public boolean hasMode() { return hasMode; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * Gimbal attitude in degrees. FW 2.3 sends the three angles only
     * (12 bytes); FW 3.1 appends a limit byte (13 bytes).
     */
    public static class Gimbal extends KaitaiStruct {

        public Gimbal(KaitaiStream _io, boolean hasLimitByte) {
            this(_io, null, null, hasLimitByte);
        }

        public Gimbal(KaitaiStream _io, KaitaiStruct _parent, boolean hasLimitByte) {
            this(_io, _parent, null, hasLimitByte);
        }

        public Gimbal(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root, boolean hasLimitByte) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            this.hasLimitByte = hasLimitByte;
            _read();
        }
        private void _read() {
            this.roll = this._io.readF4le();
            this.pitch = this._io.readF4le();
            this.yaw = this._io.readF4le();
            if (hasLimitByte()) {
                this.limit = new GimbalLimit(this._io, this, _root);
            }
        }

        public void _fetchInstances() {
            if (hasLimitByte()) {
                this.limit._fetchInstances();
            }
        }
        private float roll;
        private float pitch;
        private float yaw;
        private GimbalLimit limit;
        private boolean hasLimitByte;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * Gimbal roll, degrees.
         */
        public float roll() { return roll; }

        /**
         * Gimbal pitch, degrees.
         */
        public float pitch() { return pitch; }

        /**
         * Gimbal yaw, degrees.
         */
        public float yaw() { return yaw; }

        /**
         * Which axes are at their mechanical limit (FW 3.1 only).
         */
        public GimbalLimit limit() { return limit; }

        /**
         * true for the 13-byte FW 3.1 form
         */
        public boolean hasLimitByte() { return hasLimitByte; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * The gimbal limit byte.
     */
    public static class GimbalLimit extends KaitaiStruct {
        public static GimbalLimit fromFile(String fileName) throws IOException {
            return new GimbalLimit(new ByteBufferKaitaiStream(fileName));
        }

        public GimbalLimit(KaitaiStream _io) {
            this(_io, null, null);
        }

        public GimbalLimit(KaitaiStream _io, OsdkBroadcastItems.Gimbal _parent) {
            this(_io, _parent, null);
        }

        public GimbalLimit(KaitaiStream _io, OsdkBroadcastItems.Gimbal _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.pitchLimit = this._io.readBitsIntLe(1) != 0;
            this.rollLimit = this._io.readBitsIntLe(1) != 0;
            this.yawLimit = this._io.readBitsIntLe(1) != 0;
            this.reserved = this._io.readBitsIntLe(5);
        }

        public void _fetchInstances() {
        }
        private boolean pitchLimit;
        private boolean rollLimit;
        private boolean yawLimit;
        private long reserved;
        private OsdkBroadcastItems _root;
        private OsdkBroadcastItems.Gimbal _parent;

        /**
         * Bit 0, pitch at its limit.
         */
        public boolean pitchLimit() { return pitchLimit; }

        /**
         * Bit 1, roll at its limit.
         */
        public boolean rollLimit() { return rollLimit; }

        /**
         * Bit 2, yaw at its limit.
         */
        public boolean yawLimit() { return yawLimit; }

        /**
         * Bits 3-7, reserved; a receiver ignores them.
         */
        public long reserved() { return reserved; }
        public OsdkBroadcastItems _root() { return _root; }
        public OsdkBroadcastItems.Gimbal _parent() { return _parent; }
    }

    /**
     * Detailed GPS information, A3 family only (flag bit 6 in a3-fw3.1).
     */
    public static class GpsDetail extends KaitaiStruct {
        public static GpsDetail fromFile(String fileName) throws IOException {
            return new GpsDetail(new ByteBufferKaitaiStream(fileName));
        }

        public GpsDetail(KaitaiStream _io) {
            this(_io, null, null);
        }

        public GpsDetail(KaitaiStream _io, KaitaiStruct _parent) {
            this(_io, _parent, null);
        }

        public GpsDetail(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.date = this._io.readU4le();
            this.time = this._io.readU4le();
            this.longitude = this._io.readS4le();
            this.latitude = this._io.readS4le();
            this.heightMsl = this._io.readS4le();
            this.velN = this._io.readF4le();
            this.velE = this._io.readF4le();
            this.velD = this._io.readF4le();
        }

        public void _fetchInstances() {
        }
        private long date;
        private long time;
        private int longitude;
        private int latitude;
        private int heightMsl;
        private float velN;
        private float velE;
        private float velD;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * UTC date as the decimal number yyyymmdd.
         */
        public long date() { return date; }

        /**
         * UTC time as the decimal number hhmmss.
         */
        public long time() { return time; }

        /**
         * Longitude, degrees times 1e7. Longitude comes first in this item.
         */
        public int longitude() { return longitude; }

        /**
         * Latitude, degrees times 1e7.
         */
        public int latitude() { return latitude; }

        /**
         * Height above mean sea level, mm.
         */
        public int heightMsl() { return heightMsl; }

        /**
         * Velocity towards north, cm/s.
         */
        public float velN() { return velN; }

        /**
         * Velocity towards east, cm/s.
         */
        public float velE() { return velE; }

        /**
         * Velocity downwards, cm/s.
         */
        public float velD() { return velD; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * Raw magnetometer reading, unitless counts.
     */
    public static class Magnetometer extends KaitaiStruct {
        public static Magnetometer fromFile(String fileName) throws IOException {
            return new Magnetometer(new ByteBufferKaitaiStream(fileName));
        }

        public Magnetometer(KaitaiStream _io) {
            this(_io, null, null);
        }

        public Magnetometer(KaitaiStream _io, KaitaiStruct _parent) {
            this(_io, _parent, null);
        }

        public Magnetometer(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.x = this._io.readS2le();
            this.y = this._io.readS2le();
            this.z = this._io.readS2le();
        }

        public void _fetchInstances() {
        }
        private short x;
        private short y;
        private short z;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * x axis.
         */
        public short x() { return x; }

        /**
         * y axis.
         */
        public short y() { return y; }

        /**
         * z axis.
         */
        public short z() { return z; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * GPS position and altitude (flag bit 5). Latitude comes first on the
     * wire although the seed's table lists longitude first (ERRATA E01).
     */
    public static class Position extends KaitaiStruct {
        public static Position fromFile(String fileName) throws IOException {
            return new Position(new ByteBufferKaitaiStream(fileName));
        }

        public Position(KaitaiStream _io) {
            this(_io, null, null);
        }

        public Position(KaitaiStream _io, KaitaiStruct _parent) {
            this(_io, _parent, null);
        }

        public Position(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.latitude = this._io.readF8le();
            this.longitude = this._io.readF8le();
            this.altitude = this._io.readF4le();
            this.height = this._io.readF4le();
            this.gpsHealth = this._io.readU1();
        }

        public void _fetchInstances() {
        }
        private double latitude;
        private double longitude;
        private float altitude;
        private float height;
        private int gpsHealth;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * Latitude, radians.
         */
        public double latitude() { return latitude; }

        /**
         * Longitude, radians.
         */
        public double longitude() { return longitude; }

        /**
         * Altitude (barometer and IMU when fused, barometer when raw), m.
         */
        public float altitude() { return altitude; }

        /**
         * Height above ground (fusion with ultrasound when below 3 m), m.
         */
        public float height() { return height; }

        /**
         * GPS health, 0 (no fix) to 5 (best).
         */
        public int gpsHealth() { return gpsHealth; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * Attitude quaternion from the ground frame to the body frame (flag bit 1).
     */
    public static class Quaternion extends KaitaiStruct {
        public static Quaternion fromFile(String fileName) throws IOException {
            return new Quaternion(new ByteBufferKaitaiStream(fileName));
        }

        public Quaternion(KaitaiStream _io) {
            this(_io, null, null);
        }

        public Quaternion(KaitaiStream _io, KaitaiStruct _parent) {
            this(_io, _parent, null);
        }

        public Quaternion(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.q0 = this._io.readF4le();
            this.q1 = this._io.readF4le();
            this.q2 = this._io.readF4le();
            this.q3 = this._io.readF4le();
        }

        public void _fetchInstances() {
        }
        private float q0;
        private float q1;
        private float q2;
        private float q3;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * Scalar part.
         */
        public float q0() { return q0; }

        /**
         * Vector part, x.
         */
        public float q1() { return q1; }

        /**
         * Vector part, y.
         */
        public float q2() { return q2; }

        /**
         * Vector part, z.
         */
        public float q3() { return q3; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * Remote controller sticks and switches. Sticks range -10000..10000;
     * mode is -8000 (P), 0 (A) or 8000 (F); gear is -4545 or -10000.
     */
    public static class Rc extends KaitaiStruct {
        public static Rc fromFile(String fileName) throws IOException {
            return new Rc(new ByteBufferKaitaiStream(fileName));
        }

        public Rc(KaitaiStream _io) {
            this(_io, null, null);
        }

        public Rc(KaitaiStream _io, KaitaiStruct _parent) {
            this(_io, _parent, null);
        }

        public Rc(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.roll = this._io.readS2le();
            this.pitch = this._io.readS2le();
            this.yaw = this._io.readS2le();
            this.throttle = this._io.readS2le();
            this.mode = this._io.readS2le();
            this.gear = this._io.readS2le();
        }

        public void _fetchInstances() {
        }
        private short roll;
        private short pitch;
        private short yaw;
        private short throttle;
        private short mode;
        private short gear;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * Roll stick, -10000 (left) to 10000 (right).
         */
        public short roll() { return roll; }

        /**
         * Pitch stick, -10000 (down) to 10000 (up).
         */
        public short pitch() { return pitch; }

        /**
         * Yaw stick, -10000 (left) to 10000 (right).
         */
        public short yaw() { return yaw; }

        /**
         * Throttle stick, -10000 (down) to 10000 (up).
         */
        public short throttle() { return throttle; }

        /**
         * Flight mode switch, -8000 P, 0 A, 8000 F.
         */
        public short mode() { return mode; }

        /**
         * Gear switch, -4545 or -10000 (see rules.yaml rc_channels).
         */
        public short gear() { return gear; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * Detailed RTK information, A3 family only (flag bit 7 in a3-fw3.1).
     */
    public static class RtkDetail extends KaitaiStruct {
        public static RtkDetail fromFile(String fileName) throws IOException {
            return new RtkDetail(new ByteBufferKaitaiStream(fileName));
        }

        public RtkDetail(KaitaiStream _io) {
            this(_io, null, null);
        }

        public RtkDetail(KaitaiStream _io, KaitaiStruct _parent) {
            this(_io, _parent, null);
        }

        public RtkDetail(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
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

        public void _fetchInstances() {
        }
        private long date;
        private long time;
        private double longitude;
        private double latitude;
        private float heightMsl;
        private float velN;
        private float velE;
        private float velD;
        private short yaw;
        private int positionFlag;
        private int yawFlag;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * UTC date as the decimal number yyyymmdd.
         */
        public long date() { return date; }

        /**
         * UTC time as the decimal number hhmmss.
         */
        public long time() { return time; }

        /**
         * Longitude by RTK, degrees.
         */
        public double longitude() { return longitude; }

        /**
         * Latitude by RTK, degrees.
         */
        public double latitude() { return latitude; }

        /**
         * Height above mean sea level by RTK, m.
         */
        public float heightMsl() { return heightMsl; }

        /**
         * Velocity towards north, cm/s.
         */
        public float velN() { return velN; }

        /**
         * Velocity towards east, cm/s.
         */
        public float velE() { return velE; }

        /**
         * Velocity downwards, cm/s.
         */
        public float velD() { return velD; }

        /**
         * Angle between the antenna baseline and south, degrees.
         */
        public short yaw() { return yaw; }

        /**
         * RTK positioning solution flag.
         */
        public int positionFlag() { return positionFlag; }

        /**
         * RTK heading solution flag.
         */
        public int yawFlag() { return yawFlag; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * Time stamp item (flag bit 0). FW 2.3 sends only the 4-byte tick
     * counter; FW 3.1 adds the nanosecond counter and the sync flag (9 bytes).
     */
    public static class TimeStamp extends KaitaiStruct {

        public TimeStamp(KaitaiStream _io, boolean hasNsAndSync) {
            this(_io, null, null, hasNsAndSync);
        }

        public TimeStamp(KaitaiStream _io, KaitaiStruct _parent, boolean hasNsAndSync) {
            this(_io, _parent, null, hasNsAndSync);
        }

        public TimeStamp(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root, boolean hasNsAndSync) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            this.hasNsAndSync = hasNsAndSync;
            _read();
        }
        private void _read() {
            this.time = this._io.readU4le();
            if (hasNsAndSync()) {
                this.nanoTime = this._io.readU4le();
            }
            if (hasNsAndSync()) {
                this.syncFlag = this._io.readU1();
            }
        }

        public void _fetchInstances() {
            if (hasNsAndSync()) {
            }
            if (hasNsAndSync()) {
            }
        }
        private long time;
        private Long nanoTime;
        private Integer syncFlag;
        private boolean hasNsAndSync;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * Free-running time stamp, in ticks of 1/400 s.
         */
        public long time() { return time; }

        /**
         * Time stamp in nanoseconds (FW 3.1 only).
         */
        public Long nanoTime() { return nanoTime; }

        /**
         * Hardware sync signal flag (FW 3.1 only).
         */
        public Integer syncFlag() { return syncFlag; }

        /**
         * true for the 9-byte FW 3.1 form, false for the 4-byte FW 2.3 form
         */
        public boolean hasNsAndSync() { return hasNsAndSync; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * Three float32 components. Used for linear acceleration (m/s^2 when
     * fused, g when raw) and angular rate (rad/s); which of raw or fusion is
     * sent is a setting of the flight controller, not visible on the wire.
     */
    public static class Vector3f extends KaitaiStruct {
        public static Vector3f fromFile(String fileName) throws IOException {
            return new Vector3f(new ByteBufferKaitaiStream(fileName));
        }

        public Vector3f(KaitaiStream _io) {
            this(_io, null, null);
        }

        public Vector3f(KaitaiStream _io, KaitaiStruct _parent) {
            this(_io, _parent, null);
        }

        public Vector3f(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.x = this._io.readF4le();
            this.y = this._io.readF4le();
            this.z = this._io.readF4le();
        }

        public void _fetchInstances() {
        }
        private float x;
        private float y;
        private float z;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * x component.
         */
        public float x() { return x; }

        /**
         * y component.
         */
        public float y() { return y; }

        /**
         * z component.
         */
        public float z() { return z; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }

    /**
     * Linear velocity in the ground frame, m/s, with a status byte (flag bit 3).
     */
    public static class Velocity extends KaitaiStruct {
        public static Velocity fromFile(String fileName) throws IOException {
            return new Velocity(new ByteBufferKaitaiStream(fileName));
        }

        public Velocity(KaitaiStream _io) {
            this(_io, null, null);
        }

        public Velocity(KaitaiStream _io, KaitaiStruct _parent) {
            this(_io, _parent, null);
        }

        public Velocity(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastItems _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.x = this._io.readF4le();
            this.y = this._io.readF4le();
            this.z = this._io.readF4le();
            this.dataValid = this._io.readBitsIntLe(1) != 0;
            this.sensorId = this._io.readBitsIntLe(4);
            this.reserved = this._io.readBitsIntLe(3);
        }

        public void _fetchInstances() {
        }
        private float x;
        private float y;
        private float z;
        private boolean dataValid;
        private long sensorId;
        private long reserved;
        private OsdkBroadcastItems _root;
        private KaitaiStruct _parent;

        /**
         * Velocity along ground-frame x, m/s.
         */
        public float x() { return x; }

        /**
         * Velocity along ground-frame y, m/s.
         */
        public float y() { return y; }

        /**
         * Velocity along ground-frame z, m/s.
         */
        public float z() { return z; }

        /**
         * Status bit 0, true when the velocity is valid.
         */
        public boolean dataValid() { return dataValid; }

        /**
         * Status bits 1-4. The seed calls them reserved; the M100 SDK struct
         * names them the sensor id (ERRATA E04). Informative only.
         */
        public long sensorId() { return sensorId; }

        /**
         * Status bits 5-7, reserved; a receiver ignores them.
         */
        public long reserved() { return reserved; }
        public OsdkBroadcastItems _root() { return _root; }
        public KaitaiStruct _parent() { return _parent; }
    }
    private OsdkBroadcastItems _root;
    private KaitaiStruct _parent;
    public OsdkBroadcastItems _root() { return _root; }
    public KaitaiStruct _parent() { return _parent; }
}
