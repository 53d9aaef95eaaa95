// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

package osdk_kaitai;

import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStruct;
import io.kaitai.struct.KaitaiStream;
import java.io.IOException;
import java.util.Map;
import java.util.HashMap;


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
 * @see "osdk-conformance seed shared/seeds/000_b7658b258220b5c1.txt (Control mode byte)"
 * @see "osdk-conformance shared/reference/PROTOCOL-FACTS.md section 4"
 * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.9.0/osdk-core/api/inc/dji_control.hpp">Source</a>
 */
public class OsdkControlMode extends KaitaiStruct {
    public static OsdkControlMode fromFile(String fileName) throws IOException {
        return new OsdkControlMode(new ByteBufferKaitaiStream(fileName));
    }

    public enum HorizontalFrame {
        GROUND(0),
        BODY(1);

        private final long id;
        HorizontalFrame(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, HorizontalFrame> byId = new HashMap<Long, HorizontalFrame>(2);
        static {
            for (HorizontalFrame e : HorizontalFrame.values())
                byId.put(e.id(), e);
        }
        public static HorizontalFrame byId(long id) { return byId.get(id); }
    }

    public enum HorizontalLogic {
        HORI_ATTI_TILT_ANG(0),
        HORI_VEL(1),
        HORI_POS(2);

        private final long id;
        HorizontalLogic(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, HorizontalLogic> byId = new HashMap<Long, HorizontalLogic>(3);
        static {
            for (HorizontalLogic e : HorizontalLogic.values())
                byId.put(e.id(), e);
        }
        public static HorizontalLogic byId(long id) { return byId.get(id); }
    }

    public enum StableMode {
        NON_STABLE(0),
        STABLE(1);

        private final long id;
        StableMode(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, StableMode> byId = new HashMap<Long, StableMode>(2);
        static {
            for (StableMode e : StableMode.values())
                byId.put(e.id(), e);
        }
        public static StableMode byId(long id) { return byId.get(id); }
    }

    public enum VerticalLogic {
        VERT_VEL(0),
        VERT_POS(1),
        VERT_THRUST(2);

        private final long id;
        VerticalLogic(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, VerticalLogic> byId = new HashMap<Long, VerticalLogic>(3);
        static {
            for (VerticalLogic e : VerticalLogic.values())
                byId.put(e.id(), e);
        }
        public static VerticalLogic byId(long id) { return byId.get(id); }
    }

    public enum YawLogic {
        YAW_ANG(0),
        YAW_RATE(1);

        private final long id;
        YawLogic(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, YawLogic> byId = new HashMap<Long, YawLogic>(2);
        static {
            for (YawLogic e : YawLogic.values())
                byId.put(e.id(), e);
        }
        public static YawLogic byId(long id) { return byId.get(id); }
    }

    public OsdkControlMode(KaitaiStream _io) {
        this(_io, null, null);
    }

    public OsdkControlMode(KaitaiStream _io, KaitaiStruct _parent) {
        this(_io, _parent, null);
    }

    public OsdkControlMode(KaitaiStream _io, KaitaiStruct _parent, OsdkControlMode _root) {
        super(_io);
        this._parent = _parent;
        this._root = _root == null ? this : _root;
        _read();
    }
    private void _read() {
        this.stableMode = StableMode.byId(this._io.readBitsIntLe(1));
        this.horizontalFrame = HorizontalFrame.byId(this._io.readBitsIntLe(2));
        this.yawLogic = YawLogic.byId(this._io.readBitsIntLe(1));
        this.verticalLogic = VerticalLogic.byId(this._io.readBitsIntLe(2));
        this.horizontalLogic = HorizontalLogic.byId(this._io.readBitsIntLe(2));
    }

    public void _fetchInstances() {
    }
    private StableMode stableMode;
    private HorizontalFrame horizontalFrame;
    private YawLogic yawLogic;
    private VerticalLogic verticalLogic;
    private HorizontalLogic horizontalLogic;
    private OsdkControlMode _root;
    private KaitaiStruct _parent;

    /**
     * Bit 0. Stable mode on FW 3.1 profiles; it affects horizontal control
     * only. On m100-fw2.3 the same bit selects the yaw frame (0 ground,
     * 1 body) and must be 0 with yaw angle (ERRATA E15, rules.yaml
     * control_mode.bit0_by_profile).
     */
    public StableMode stableMode() { return stableMode; }

    /**
     * Bits 2-1. Reference frame of the horizontal setpoints.
     */
    public HorizontalFrame horizontalFrame() { return horizontalFrame; }

    /**
     * Bit 3. Yaw setpoint is an angle (ground frame enforced) or a rate.
     */
    public YawLogic yawLogic() { return yawLogic; }

    /**
     * Bits 5-4. Meaning of the vertical (throttle) setpoint.
     */
    public VerticalLogic verticalLogic() { return verticalLogic; }

    /**
     * Bits 7-6. Meaning of the two horizontal (roll, pitch) setpoints.
     */
    public HorizontalLogic horizontalLogic() { return horizontalLogic; }
    public OsdkControlMode _root() { return _root; }
    public KaitaiStruct _parent() { return _parent; }
}
