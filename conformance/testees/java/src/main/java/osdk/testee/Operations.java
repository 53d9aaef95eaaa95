package osdk.testee;

import java.math.BigInteger;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import osdk_kaitai.OsdkControlMode;
import osdk_kaitai.OsdkFrame;
import osdk_kaitai.OsdkMovementControl;
import osdk_kaitai.OsdkPayload;

/**
 * The operations of conformance/PROTOCOL.md over the generated parsers, as
 * conformance/testees/kaitai_python_testee.py does them.
 */
final class Operations {
    static final String NAME = "osdk-kaitai-java";
    static final List<String> OPERATIONS = List.of(
            "decode_stream", "decode_frame", "decode_payload", "classify_control_mode", "check_movement_control");

    private static final Tables T = Tables.INSTANCE;
    private static final Pattern HEX = Pattern.compile("(?:[0-9a-fA-F]{2})*");
    // setpoint -> the range it is checked against, in the order the reference checks them
    private static final String[][] AXES = {{"x", "horizontal"}, {"y", "horizontal"}, {"z", "vertical"}, {"yaw", "yaw"}};

    private Operations() {
    }

    /** The response object to one request (bad requests throw BadRequest). */
    static Map<String, Object> answer(Map<String, Object> req) {
        String op = (String) req.get("op");
        if (op.equals("capabilities")) {
            Map<String, Object> caps = new LinkedHashMap<>();
            caps.put("name", NAME);
            caps.put("operations", OPERATIONS);
            caps.put("profiles", T.profiles);
            return ok(caps);
        }
        Object profile = req.get("profile");
        if (!OPERATIONS.contains(op) || !(profile instanceof String) || !T.profiles.contains(profile)) {
            Map<String, Object> out = new LinkedHashMap<>();
            out.put("ok", false);
            out.put("unsupported", true);
            return out;
        }
        String p = (String) profile;
        try {
            switch (op) {
                case "decode_stream":
                    return ok(decodeStream(req, p));
                case "decode_frame":
                    return ok(decodeFrame(req, p));
                case "decode_payload":
                    return ok(decodePayload(req, p));
                case "classify_control_mode":
                    return ok(classify(req, p));
                default:
                    return ok(checkMovementControl(req, p));
            }
        } catch (Rejection r) {
            Map<String, Object> out = new LinkedHashMap<>();
            out.put("ok", false);
            out.put("error", r.cls);
            out.put("detail", r.detail);
            return out;
        }
    }

    private static Map<String, Object> ok(Object result) {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("ok", true);
        out.put("result", result);
        return out;
    }

    // ---- the generated parsers -------------------------------------------------------------

    static OsdkPayload.Profile profile(String name) {
        Long value = T.profileValues.get(name);
        OsdkPayload.Profile p = value == null ? null : OsdkPayload.Profile.byId(value);
        if (p == null) {
            throw new IllegalStateException("profile " + name + " has no value of the enum osdk_payload.profile");
        }
        return p;
    }

    static OsdkFrame frame(byte[] raw, String profile) throws Rejection {
        return Kaitai.parse(io -> new OsdkFrame(io, profile(profile)), raw);
    }

    static OsdkPayload payload(byte[] data, int cmdSet, int cmdId, boolean isAck, String profile) throws Rejection {
        return Kaitai.parse(io -> new OsdkPayload(io, cmdSet, cmdId, isAck, profile(profile)), data);
    }

    /** The model of osdk_payload's body. */
    static Object bodyModel(OsdkPayload p, byte[] data) {
        return ValueModel.of(p, data).get("body");
    }

    // ---- operations --------------------------------------------------------------------------

    private static Map<String, Object> decodePayload(Map<String, Object> req, String profile) throws Rejection {
        byte[] data = hexArg(req);
        int cmdSet = byteArg(req, "cmd_set");
        int cmdId = byteArg(req, "cmd_id");
        boolean isAck = boolArg(req, "is_ack");
        OsdkPayload p = payload(data, cmdSet, cmdId, isAck, profile);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("value", bodyModel(p, data));
        return out;
    }

    private static Map<String, Object> classify(Map<String, Object> req, String profile) throws Rejection {
        int b = byteArg(req, "byte");
        byte[] data = {(byte) b};
        OsdkControlMode mode = Kaitai.parse(OsdkControlMode::new, data);
        Tables.Mode c = T.mode(profile, b);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("fields", ValueModel.of(mode, data));
        out.put("classification", c.classification);
        out.put("combination", c.combination);
        return out;
    }

    private static Map<String, Object> checkMovementControl(Map<String, Object> req, String profile) throws Rejection {
        byte[] data = hexArg(req);
        // As a command value, so that bytes left over are length_mismatch as in a frame.
        OsdkPayload p = payload(data, 0x01, 0x03, false, profile);
        OsdkMovementControl body = (OsdkMovementControl) p.body();
        Object value = bodyModel(p, data);
        int modeByte = data[0] & 0xFF;
        Tables.Mode c = T.mode(profile, modeByte);
        if (!c.classification.equals("documented")) {
            throw new Rejection("undefined_mode",
                    String.format("mode byte 0x%02x is %s on %s", modeByte, c.classification, profile));
        }
        double[] setpoints = {body.x(), body.y(), body.z(), body.yaw()};
        for (int i = 0; i < AXES.length; i++) {
            double v = setpoints[i];
            Tables.Range r = T.range(profile, c.combination, AXES[i][1]);
            if (Double.isNaN(v) || Double.isInfinite(v) || (r.min != null && v < r.min) || (r.max != null && v > r.max)) {
                throw new Rejection("out_of_range", AXES[i][0] + " = " + v + " outside the " + AXES[i][1] + " range "
                        + r.min + ".." + r.max);
            }
        }
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("value", value);
        out.put("combination", c.combination);
        return out;
    }

    private static Map<String, Object> decodeFrame(Map<String, Object> req, String profile) throws Rejection {
        byte[] data = hexArg(req);
        // The receiver's checks, in the order a receiver meets them.
        if (data.length == 0) {
            throw new Rejection("truncated_frame", "no bytes");
        }
        if ((data[0] & 0xFF) != Deframer.SOF) {
            throw new Rejection("bad_sof", String.format("first byte 0x%02x is not the start byte", data[0] & 0xFF));
        }
        if (data.length < Deframer.HEADER_LEN) {
            throw new Rejection("truncated_frame", data.length + " bytes, less than a header");
        }
        Rejection problem = Deframer.headerProblem(data, 0);
        if (problem != null) {
            throw problem;
        }
        int length = Deframer.frameLength(data, 0);
        if (data.length < length) {
            throw new Rejection("truncated_frame", data.length + " bytes of a frame of LEN " + length);
        }
        if (data.length > length) {
            throw new Rejection("length_mismatch", data.length + " bytes for LEN " + length);
        }
        if (Deframer.crc32Fails(data, 0, length)) {
            throw new Rejection("bad_crc32", "CRC-32 does not match");
        }
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("frame", ValueModel.of(frame(data, profile), data));
        return out;
    }

    private static Map<String, Object> decodeStream(Map<String, Object> req, String profile) {
        byte[] data = hexArg(req);
        List<Long> sizes = chunksArg(req);
        List<Object> events = new ArrayList<>();
        EventStream stream = new EventStream(profile, true, events::add);
        for (byte[] chunk : Deframer.splitChunks(data, sizes)) {
            stream.feed(chunk, chunk.length);
        }
        stream.finish();
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("events", events);
        return out;
    }

    // ---- arguments ------------------------------------------------------------------------------

    private static Object arg(Map<String, Object> req, String key) {
        if (!req.containsKey(key)) {
            throw new BadRequest("missing argument '" + key + "'");
        }
        return req.get(key);
    }

    private static byte[] hexArg(Map<String, Object> req) {
        Object v = arg(req, "hex");
        if (!(v instanceof String) || !HEX.matcher((String) v).matches()) {
            throw new BadRequest("argument 'hex' is not a hex string of whole bytes");
        }
        String s = (String) v;
        byte[] out = new byte[s.length() / 2];
        for (int i = 0; i < out.length; i++) {
            out[i] = (byte) Integer.parseInt(s.substring(2 * i, 2 * i + 2), 16);
        }
        return out;
    }

    private static int byteArg(Map<String, Object> req, String key) {
        Object v = arg(req, key);
        if (!(v instanceof Long) && !(v instanceof BigInteger)) {
            throw new BadRequest("argument '" + key + "' must be an integer");
        }
        if (!(v instanceof Long) || (Long) v < 0 || (Long) v > 0xFF) {
            throw new BadRequest("argument '" + key + "' must be 0..255");
        }
        return (int) (long) (Long) v;
    }

    private static boolean boolArg(Map<String, Object> req, String key) {
        Object v = arg(req, key);
        if (!(v instanceof Boolean)) {
            throw new BadRequest("argument '" + key + "' must be a boolean");
        }
        return (Boolean) v;
    }

    private static List<Long> chunksArg(Map<String, Object> req) {
        Object v = arg(req, "chunks");
        if (!(v instanceof List)) {
            throw new BadRequest("argument 'chunks' must be a list");
        }
        List<Long> out = new ArrayList<>();
        for (Object o : (List<?>) v) {
            if (o instanceof Long && (Long) o >= 0) {
                out.add((Long) o);
            } else if (o instanceof BigInteger && ((BigInteger) o).signum() >= 0) {
                out.add(Long.MAX_VALUE); // more than any input: the same cut
            } else {
                throw new BadRequest("argument 'chunks' must be a list of non-negative integers");
            }
        }
        return out;
    }
}
