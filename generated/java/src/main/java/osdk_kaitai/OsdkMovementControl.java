// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

package osdk_kaitai;

import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStruct;
import io.kaitai.struct.KaitaiStream;
import java.io.IOException;


/**
 * The 17-byte value of the movement control command an onboard device sends
 * (in session 0, no ACK) while it holds control authority: a control mode
 * byte and four float32 setpoints whose meaning and units the mode byte
 * selects. Ranges per combination and profile are in rules.yaml
 * (control_modes).
 * @see "osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2"
 * @see <a href="https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md">Source</a>
 */
public class OsdkMovementControl extends KaitaiStruct {
    public static OsdkMovementControl fromFile(String fileName) throws IOException {
        return new OsdkMovementControl(new ByteBufferKaitaiStream(fileName));
    }

    public OsdkMovementControl(KaitaiStream _io) {
        this(_io, null, null);
    }

    public OsdkMovementControl(KaitaiStream _io, KaitaiStruct _parent) {
        this(_io, _parent, null);
    }

    public OsdkMovementControl(KaitaiStream _io, KaitaiStruct _parent, OsdkMovementControl _root) {
        super(_io);
        this._parent = _parent;
        this._root = _root == null ? this : _root;
        _read();
    }
    private void _read() {
        this.controlMode = new OsdkControlMode(this._io);
        this.x = this._io.readF4le();
        this.y = this._io.readF4le();
        this.z = this._io.readF4le();
        this.yaw = this._io.readF4le();
    }

    public void _fetchInstances() {
        this.controlMode._fetchInstances();
    }
    private OsdkControlMode controlMode;
    private float x;
    private float y;
    private float z;
    private float yaw;
    private OsdkMovementControl _root;
    private KaitaiStruct _parent;

    /**
     * How the four setpoints are to be interpreted.
     */
    public OsdkControlMode controlMode() { return controlMode; }

    /**
     * Roll angle (deg), x velocity (m/s) or x offset (m), per horizontal logic and frame.
     */
    public float x() { return x; }

    /**
     * Pitch angle (deg), y velocity (m/s) or y offset (m), per horizontal logic and frame.
     */
    public float y() { return y; }

    /**
     * Vertical velocity (m/s), height (m) or thrust (%), per vertical logic.
     */
    public float z() { return z; }

    /**
     * Yaw angle (deg) or yaw rate (deg/s), per yaw logic.
     */
    public float yaw() { return yaw; }
    public OsdkMovementControl _root() { return _root; }
    public KaitaiStruct _parent() { return _parent; }
}
