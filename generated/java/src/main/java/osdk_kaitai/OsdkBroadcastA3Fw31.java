// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

package osdk_kaitai;

import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStruct;
import io.kaitai.struct.KaitaiStream;
import java.io.IOException;


/**
 * Payload of the flight data broadcast (command set 0x02, id 0x00) as sent
 * by A3, N3 and M600 with firmware 3.1 (OSDK 3.1). A u2 flag word says which items follow; the items follow in
 * flag-bit order, each only when its bit is set. This profile uses
 * the 9-byte time stamp, the GPS and RTK detail items at bits 6 and 7, the 13-byte gimbal item and the 2-byte control info item.
 * A flag word that promises more bytes than the payload holds is an error
 * (the DJI SDK reads past the end instead; spec/ERRATA.md E25), and so are set
 * reserved flag bits and bytes left over after the last item.
 * @see "osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3 (profile a3-fw3.1)"
 * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_App.cpp">Source</a>
 */
public class OsdkBroadcastA3Fw31 extends KaitaiStruct {
    public static OsdkBroadcastA3Fw31 fromFile(String fileName) throws IOException {
        return new OsdkBroadcastA3Fw31(new ByteBufferKaitaiStream(fileName));
    }

    public OsdkBroadcastA3Fw31(KaitaiStream _io) {
        this(_io, null, null);
    }

    public OsdkBroadcastA3Fw31(KaitaiStream _io, KaitaiStruct _parent) {
        this(_io, _parent, null);
    }

    public OsdkBroadcastA3Fw31(KaitaiStream _io, KaitaiStruct _parent, OsdkBroadcastA3Fw31 _root) {
        super(_io);
        this._parent = _parent;
        this._root = _root == null ? this : _root;
        _read();
    }
    private void _read() {
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
        if (hasTimeStamp()) {
            this.timeStamp = new OsdkBroadcastItems.TimeStamp(this._io, true);
        }
        if (hasQuaternion()) {
            this.quaternion = new OsdkBroadcastItems.Quaternion(this._io);
        }
        if (hasAcceleration()) {
            this.acceleration = new OsdkBroadcastItems.Vector3f(this._io);
        }
        if (hasVelocity()) {
            this.velocity = new OsdkBroadcastItems.Velocity(this._io);
        }
        if (hasAngularRate()) {
            this.angularRate = new OsdkBroadcastItems.Vector3f(this._io);
        }
        if (hasPosition()) {
            this.position = new OsdkBroadcastItems.Position(this._io);
        }
        if (hasGpsDetail()) {
            this.gpsDetail = new OsdkBroadcastItems.GpsDetail(this._io);
        }
        if (hasRtkDetail()) {
            this.rtkDetail = new OsdkBroadcastItems.RtkDetail(this._io);
        }
        if (hasMagnetometer()) {
            this.magnetometer = new OsdkBroadcastItems.Magnetometer(this._io);
        }
        if (hasRc()) {
            this.rc = new OsdkBroadcastItems.Rc(this._io);
        }
        if (hasGimbal()) {
            this.gimbal = new OsdkBroadcastItems.Gimbal(this._io, true);
        }
        if (hasFlightStatus()) {
            this.flightStatus = this._io.readU1();
        }
        if (hasBattery()) {
            this.battery = this._io.readU1();
        }
        if (hasControlInfo()) {
            this.controlInfo = new OsdkBroadcastItems.ControlInfo(this._io, true);
        }
        this.trailing = this._io.readBytesFull();
        {
            byte[] _it = this.trailing;
            if (!(_it.length == 0)) {
                throw new KaitaiStream.ValidationExprError(this.trailing, this._io, "/seq/29");
            }
        }
    }

    public void _fetchInstances() {
        if (hasTimeStamp()) {
            this.timeStamp._fetchInstances();
        }
        if (hasQuaternion()) {
            this.quaternion._fetchInstances();
        }
        if (hasAcceleration()) {
            this.acceleration._fetchInstances();
        }
        if (hasVelocity()) {
            this.velocity._fetchInstances();
        }
        if (hasAngularRate()) {
            this.angularRate._fetchInstances();
        }
        if (hasPosition()) {
            this.position._fetchInstances();
        }
        if (hasGpsDetail()) {
            this.gpsDetail._fetchInstances();
        }
        if (hasRtkDetail()) {
            this.rtkDetail._fetchInstances();
        }
        if (hasMagnetometer()) {
            this.magnetometer._fetchInstances();
        }
        if (hasRc()) {
            this.rc._fetchInstances();
        }
        if (hasGimbal()) {
            this.gimbal._fetchInstances();
        }
        if (hasFlightStatus()) {
        }
        if (hasBattery()) {
        }
        if (hasControlInfo()) {
            this.controlInfo._fetchInstances();
        }
    }
    private boolean hasTimeStamp;
    private boolean hasQuaternion;
    private boolean hasAcceleration;
    private boolean hasVelocity;
    private boolean hasAngularRate;
    private boolean hasPosition;
    private boolean hasGpsDetail;
    private boolean hasRtkDetail;
    private boolean hasMagnetometer;
    private boolean hasRc;
    private boolean hasGimbal;
    private boolean hasFlightStatus;
    private boolean hasBattery;
    private boolean hasControlInfo;
    private long reservedFlags;
    private OsdkBroadcastItems.TimeStamp timeStamp;
    private OsdkBroadcastItems.Quaternion quaternion;
    private OsdkBroadcastItems.Vector3f acceleration;
    private OsdkBroadcastItems.Velocity velocity;
    private OsdkBroadcastItems.Vector3f angularRate;
    private OsdkBroadcastItems.Position position;
    private OsdkBroadcastItems.GpsDetail gpsDetail;
    private OsdkBroadcastItems.RtkDetail rtkDetail;
    private OsdkBroadcastItems.Magnetometer magnetometer;
    private OsdkBroadcastItems.Rc rc;
    private OsdkBroadcastItems.Gimbal gimbal;
    private Integer flightStatus;
    private Integer battery;
    private OsdkBroadcastItems.ControlInfo controlInfo;
    private byte[] trailing;
    private OsdkBroadcastA3Fw31 _root;
    private KaitaiStruct _parent;

    /**
     * Flag bit 0, the time stamp item is present.
     */
    public boolean hasTimeStamp() { return hasTimeStamp; }

    /**
     * Flag bit 1, the quaternion item is present.
     */
    public boolean hasQuaternion() { return hasQuaternion; }

    /**
     * Flag bit 2, the acceleration item is present.
     */
    public boolean hasAcceleration() { return hasAcceleration; }

    /**
     * Flag bit 3, the velocity item is present.
     */
    public boolean hasVelocity() { return hasVelocity; }

    /**
     * Flag bit 4, the angular rate item is present.
     */
    public boolean hasAngularRate() { return hasAngularRate; }

    /**
     * Flag bit 5, the position item is present.
     */
    public boolean hasPosition() { return hasPosition; }

    /**
     * Flag bit 6, the gps detail item is present.
     */
    public boolean hasGpsDetail() { return hasGpsDetail; }

    /**
     * Flag bit 7, the rtk detail item is present.
     */
    public boolean hasRtkDetail() { return hasRtkDetail; }

    /**
     * Flag bit 8, the magnetometer item is present.
     */
    public boolean hasMagnetometer() { return hasMagnetometer; }

    /**
     * Flag bit 9, the rc item is present.
     */
    public boolean hasRc() { return hasRc; }

    /**
     * Flag bit 10, the gimbal item is present.
     */
    public boolean hasGimbal() { return hasGimbal; }

    /**
     * Flag bit 11, the flight status item is present.
     */
    public boolean hasFlightStatus() { return hasFlightStatus; }

    /**
     * Flag bit 12, the battery item is present.
     */
    public boolean hasBattery() { return hasBattery; }

    /**
     * Flag bit 13, the control info item is present.
     */
    public boolean hasControlInfo() { return hasControlInfo; }

    /**
     * Flag bits 14-15 carry no item in this profile and must be 0.
     */
    public long reservedFlags() { return reservedFlags; }

    /**
     * Time stamp.
     */
    public OsdkBroadcastItems.TimeStamp timeStamp() { return timeStamp; }

    /**
     * Attitude quaternion, ground to body.
     */
    public OsdkBroadcastItems.Quaternion quaternion() { return quaternion; }

    /**
     * Linear acceleration (m/s^2 fused, g raw).
     */
    public OsdkBroadcastItems.Vector3f acceleration() { return acceleration; }

    /**
     * Linear velocity in the ground frame, m/s.
     */
    public OsdkBroadcastItems.Velocity velocity() { return velocity; }

    /**
     * Angular rate, rad/s.
     */
    public OsdkBroadcastItems.Vector3f angularRate() { return angularRate; }

    /**
     * GPS position, altitude, height and GPS health.
     */
    public OsdkBroadcastItems.Position position() { return position; }

    /**
     * Detailed GPS information.
     */
    public OsdkBroadcastItems.GpsDetail gpsDetail() { return gpsDetail; }

    /**
     * Detailed RTK information.
     */
    public OsdkBroadcastItems.RtkDetail rtkDetail() { return rtkDetail; }

    /**
     * Magnetometer counts.
     */
    public OsdkBroadcastItems.Magnetometer magnetometer() { return magnetometer; }

    /**
     * Remote controller channels.
     */
    public OsdkBroadcastItems.Rc rc() { return rc; }

    /**
     * Gimbal attitude.
     */
    public OsdkBroadcastItems.Gimbal gimbal() { return gimbal; }

    /**
     * Flight status; old or new enum by aircraft and firmware (rules.yaml flight_status).
     */
    public Integer flightStatus() { return flightStatus; }

    /**
     * Battery capacity, percent (0-100).
     */
    public Integer battery() { return battery; }

    /**
     * Source of control.
     */
    public OsdkBroadcastItems.ControlInfo controlInfo() { return controlInfo; }

    /**
     * Bytes after the last present item; a conforming payload has none.
     */
    public byte[] trailing() { return trailing; }
    public OsdkBroadcastA3Fw31 _root() { return _root; }
    public KaitaiStruct _parent() { return _parent; }
}
