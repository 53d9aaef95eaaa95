package osdk.testee;

import java.math.BigInteger;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStruct;
import osdk_kaitai.Osdk;
import osdk_kaitai.OsdkControlMode;
import osdk_kaitai.OsdkException;
import osdk_kaitai.OsdkMovementControl;

/**
 * The operations of conformance/PROTOCOL.md over the generated library
 * (osdk_kaitai: decodeFrame, decodePayload, the Deframer, the encoders), as
 * conformance/testees/kaitai_python_testee.py does them.
 */
final class Operations {
    static final String NAME = "osdk-kaitai-java";
    static final List<String> OPERATIONS = List.of(
            "decode_stream", "decode_frame", "decode_payload", "classify_control_mode", "check_movement_control",
            "encode_movement_control", "encode_frame");
    // their requests carry no profile
    private static final List<String> NO_PROFILE = List.of("encode_movement_control", "encode_frame");

    private static final Tables T = Tables.INSTANCE;
    private static final Pattern HEX = Pattern.compile("(?:[0-9a-fA-F]{2})*");
    private static final Pattern F32 = Pattern.compile("0x[0-9a-fA-F]{8}");
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
        Object profile = NO_PROFILE.contains(op) ? "" : req.get("profile");
        if (!OPERATIONS.contains(op) || !(profile instanceof String)
                || !(NO_PROFILE.contains(op) || T.profiles.contains(profile))) {
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
                case "encode_movement_control":
                    return ok(encodeMovementControl(req));
                case "encode_frame":
                    return ok(encodeFrame(req));
                default:
                    return ok(checkMovementControl(req, p));
            }
        } catch (OsdkException r) {
            Map<String, Object> out = new LinkedHashMap<>();
            out.put("ok", false);
            out.put("error", r.errorClass());
            out.put("detail", r.detail());
            return out;
        }
    }

    private static Map<String, Object> ok(Object result) {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("ok", true);
        out.put("result", result);
        return out;
    }

    /** The model of osdk_payload's body (decodePayload's result), parsed from the whole of data. */
    static Object bodyModel(KaitaiStruct body, byte[] data) {
        return ValueModel.of(body, data);
    }

    // ---- operations --------------------------------------------------------------------------

    private static Map<String, Object> decodePayload(Map<String, Object> req, String profile) {
        byte[] data = hexArg(req);
        int cmdSet = byteArg(req, "cmd_set");
        int cmdId = byteArg(req, "cmd_id");
        boolean isAck = boolArg(req, "is_ack");
        KaitaiStruct body = Osdk.decodePayload(data, cmdSet, cmdId, isAck, profile);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("value", bodyModel(body, data));
        return out;
    }

    private static Map<String, Object> classify(Map<String, Object> req, String profile) {
        int b = byteArg(req, "byte");
        byte[] data = {(byte) b};
        OsdkControlMode mode = new OsdkControlMode(new ByteBufferKaitaiStream(data)); // one byte always parses
        Tables.Mode c = T.mode(profile, b);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("fields", ValueModel.of(mode, data));
        out.put("classification", c.classification);
        out.put("combination", c.combination);
        return out;
    }

    private static Map<String, Object> checkMovementControl(Map<String, Object> req, String profile) {
        byte[] data = hexArg(req);
        // As a command value, so that bytes left over are length_mismatch as in a frame.
        OsdkMovementControl body = (OsdkMovementControl) Osdk.decodePayload(data, 0x01, 0x03, false, profile);
        Object value = bodyModel(body, data);
        int modeByte = data[0] & 0xFF;
        Tables.Mode c = T.mode(profile, modeByte);
        if (!c.classification.equals("documented")) {
            throw new OsdkException("undefined_mode", "control_mode",
                    String.format("mode byte 0x%02x is %s on %s", modeByte, c.classification, profile));
        }
        double[] setpoints = {body.x(), body.y(), body.z(), body.yaw()};
        for (int i = 0; i < AXES.length; i++) {
            double v = setpoints[i];
            Tables.Range r = T.range(profile, c.combination, AXES[i][1]);
            if (Double.isNaN(v) || Double.isInfinite(v) || (r.min != null && v < r.min) || (r.max != null && v > r.max)) {
                throw new OsdkException("out_of_range", AXES[i][0], AXES[i][0] + " = " + v + " outside the " + AXES[i][1] + " range "
                        + r.min + ".." + r.max);
            }
        }
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("value", value);
        out.put("combination", c.combination);
        return out;
    }

    private static Map<String, Object> decodeFrame(Map<String, Object> req, String profile) {
        byte[] data = hexArg(req);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("frame", ValueModel.of(Osdk.decodeFrame(data, profile), data));
        return out;
    }

    private static Map<String, Object> encodeMovementControl(Map<String, Object> req) {
        int mode = byteArg(req, "mode");
        byte[] value = Osdk.encodeMovementControlBits(mode, f32Arg(req, "x"), f32Arg(req, "y"), f32Arg(req, "z"),
                f32Arg(req, "yaw"));
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("hex", HexFormat.of().formatHex(value));
        return out;
    }

    private static Map<String, Object> encodeFrame(Map<String, Object> req) {
        boolean isAck = boolArg(req, "is_ack");
        int cmdSet = 0;
        int cmdId = 0;
        if (!isAck) {
            cmdSet = byteArg(req, "cmd_set");
            cmdId = byteArg(req, "cmd_id");
        } else if (req.containsKey("cmd_set") || req.containsKey("cmd_id")) {
            throw new BadRequest("an ACK has no cmd_set or cmd_id");
        }
        int session = intArg(req, "session", 31);
        int seq = intArg(req, "seq", 0xFFFF);
        byte[] value = hexArg(req, "value");
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("hex", HexFormat.of().formatHex(Osdk.encodeFrame(cmdSet, cmdId, isAck, session, seq, value)));
        return out;
    }

    private static Map<String, Object> decodeStream(Map<String, Object> req, String profile) {
        byte[] data = hexArg(req);
        List<Long> sizes = chunksArg(req);
        List<Object> events = new ArrayList<>();
        EventStream stream = new EventStream(profile, true, events::add);
        for (byte[] chunk : splitChunks(data, sizes)) {
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
        return hexArg(req, "hex");
    }

    private static byte[] hexArg(Map<String, Object> req, String key) {
        Object v = arg(req, key);
        if (!(v instanceof String) || !HEX.matcher((String) v).matches()) {
            throw new BadRequest("argument '" + key + "' is not a hex string of whole bytes");
        }
        String s = (String) v;
        byte[] out = new byte[s.length() / 2];
        for (int i = 0; i < out.length; i++) {
            out[i] = (byte) Integer.parseInt(s.substring(2 * i, 2 * i + 2), 16);
        }
        return out;
    }

    private static int byteArg(Map<String, Object> req, String key) {
        return intArg(req, key, 0xFF);
    }

    private static int intArg(Map<String, Object> req, String key, int max) {
        Object v = arg(req, key);
        if (!(v instanceof Long) && !(v instanceof BigInteger)) {
            throw new BadRequest("argument '" + key + "' must be an integer");
        }
        if (!(v instanceof Long) || (Long) v < 0 || (Long) v > max) {
            throw new BadRequest("argument '" + key + "' must be 0.." + max);
        }
        return (int) (long) (Long) v;
    }

    /** A float argument {"f32": "0x..."}: its IEEE bits, so that every NaN payload survives. */
    private static int f32Arg(Map<String, Object> req, String key) {
        Object v = arg(req, key);
        Object bits = v instanceof Map ? ((Map<?, ?>) v).get("f32") : null;
        if (!(bits instanceof String) || !F32.matcher((String) bits).matches()) {
            throw new BadRequest("argument '" + key + "' must be {\"f32\": \"0x<8 hex digits>\"}");
        }
        return (int) Long.parseLong(((String) bits).substring(2), 16);
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

    /** data cut into reads of the given sizes; what they leave over is one last read. */
    static List<byte[]> splitChunks(byte[] data, List<Long> sizes) {
        List<byte[]> out = new ArrayList<>();
        int pos = 0;
        for (long size : sizes) {
            int n = (int) Math.min(size, data.length); // a longer read takes no more than all
            int from = Math.min(pos, data.length);
            int to = (int) Math.min((long) pos + n, data.length);
            out.add(java.util.Arrays.copyOfRange(data, from, to));
            pos = (int) Math.min((long) pos + n, data.length);
        }
        if (pos < data.length) {
            out.add(java.util.Arrays.copyOfRange(data, pos, data.length));
        }
        return out;
    }
}
