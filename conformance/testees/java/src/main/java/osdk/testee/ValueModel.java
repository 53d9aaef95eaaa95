package osdk.testee;

import io.kaitai.struct.KaitaiStruct;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The JSON value model (docs/VALUE-MODEL.md) of a generated object, fields
 * and their kinds from the tables (`model`).
 *
 * Two things the Java object cannot say are taken from the input bytes the
 * object was parsed from, at the field's offset:
 *
 * - the number of an enum value the spec has no name for: the generated
 *   code stores `Enum.byId(raw)`, which is null for such a value;
 * - the bits of a NaN float, as a guard: should a signalling NaN come back
 *   quieted, the model still shows the wire's bits. The bits read must be
 *   the NaN Kaitai returned modulo the quiet bit, or the testee reports an
 *   internal error rather than guess.
 *
 * Offsets are followed while rendering, in wire order, the way the Kaitai
 * runtime reads: every type here is fixed-size given the fields already
 * read. Bit fields are packed (little-endian bit order) and a byte-sized
 * read aligns to the next byte; a field whose `if` was false takes no room;
 * a sub-object with its own substream (`size:`, `size-eos:`) starts at the
 * current byte and moves its parent on by the substream's size; any other
 * sub-object continues in its parent's stream, bit position included.
 */
final class ValueModel {
    private static final Tables T = Tables.INSTANCE;
    private static final HexFormat HEX = HexFormat.of();

    private final byte[] buf;
    private long bit; // the read position in buf, in bits

    private ValueModel(byte[] buf) {
        this.buf = buf;
    }

    /** The model of `obj`, which was parsed from the whole of `buf`. */
    static Map<String, Object> of(KaitaiStruct obj, byte[] buf) {
        return new ValueModel(buf).struct(obj);
    }

    private Map<String, Object> struct(KaitaiStruct obj) {
        Tables.Type type = T.typeOf(obj.getClass());
        Map<String, Object> out = new LinkedHashMap<>();
        for (Tables.Field f : type.fields) {
            Object v = Accessors.get(obj, f.accessor);
            if (v == null && !(f.enumKey != null && present(obj, type, f))) {
                if (!f.optional) {
                    throw new IllegalStateException(type.key + "." + f.id + " is null but has no `if`");
                }
                continue; // its `if` was false
            }
            if (f.repeat) {
                List<Object> items = new ArrayList<>();
                for (Object item : (List<?>) v) {
                    items.add(field(obj, f, item));
                }
                out.put(f.id, items);
            } else {
                out.put(f.id, field(obj, f, v));
            }
        }
        return out;
    }

    /** Whether an enum field that holds null was read (its value then has no name). */
    private static boolean present(KaitaiStruct obj, Tables.Type type, Tables.Field f) {
        if (!f.optional) {
            return true;
        }
        String expr = type.conditions.get(f.id);
        if (expr == null) {
            throw new IllegalStateException("no `if` for " + type.key + "." + f.id + " in the tables");
        }
        return Conditions.holds(obj, expr);
    }

    private Object field(KaitaiStruct parent, Tables.Field f, Object v) {
        switch (f.kind) {
            case "bool":
                return checked(f, readBits(f.widthBits) != 0 ? 1 : 0, (Boolean) v ? 1 : 0) != 0;
            case "bits": {
                long raw = readBits(f.widthBits);
                return f.enumKey != null ? enumModel(f, v, raw) : checked(f, raw, ((Number) v).longValue());
            }
            case "int": {
                align();
                long raw = readInt(f.width, f.signed);
                return f.enumKey != null ? enumModel(f, v, raw) : checked(f, raw, ((Number) v).longValue());
            }
            case "float":
                align();
                return floatModel(f, v);
            case "bytes":
                return bytes(v);
            case "struct":
            case "switch":
                if (v instanceof byte[]) {
                    return bytes(v); // a switch's fallback to raw bytes (encrypted DATA)
                }
                return child(parent, (KaitaiStruct) v);
            default:
                throw new IllegalStateException("no model for the field kind " + f.kind);
        }
    }

    private Object child(KaitaiStruct parent, KaitaiStruct sub) {
        if (sub._io() == parent._io()) {
            return struct(sub);
        }
        align();
        long start = bit;
        Map<String, Object> m = struct(sub);
        bit = start + 8 * sub._io().size();
        return m;
    }

    private String bytes(Object v) {
        align();
        byte[] b = (byte[]) v;
        bit += 8L * b.length;
        return HEX.formatHex(b);
    }

    // What Kaitai read must be what the offsets point at: a cheap proof that
    // the bytes used for unnamed enum values and NaNs are the right ones.
    private static long checked(Tables.Field f, long wire, long kaitai) {
        if (wire != kaitai) {
            throw new IllegalStateException("offset error at " + f.id + ": wire " + wire + ", Kaitai " + kaitai);
        }
        return kaitai;
    }

    private Map<String, Object> enumModel(Tables.Field f, Object constant, long raw) {
        long value = constant == null ? raw : checked(f, raw, Accessors.enumId(constant));
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("value", value);
        m.put("name", T.enumName(f.enumKey, value));
        return m;
    }

    private Map<String, Object> floatModel(Tables.Field f, Object v) {
        Map<String, Object> m = new LinkedHashMap<>();
        if (f.width == 4) {
            float x = (Float) v;
            int bits = Float.floatToRawIntBits(x);
            int wire = (int) readInt(4, false);
            if (Float.isNaN(x)) {
                if (!Float.isNaN(Float.intBitsToFloat(wire)) || (bits != wire && bits != (wire | 1 << 22))) {
                    throw nanGuard(f, Integer.toHexString(wire), Integer.toHexString(bits));
                }
                bits = wire;
            }
            checked(f, wire, bits);
            m.put("f32", String.format("0x%08x", bits));
            m.put("value", readable((double) x));
        } else {
            double x = (Double) v;
            long bits = Double.doubleToRawLongBits(x);
            long wire = readInt(8, false);
            if (Double.isNaN(x)) {
                if (!Double.isNaN(Double.longBitsToDouble(wire)) || (bits != wire && bits != (wire | 1L << 51))) {
                    throw nanGuard(f, Long.toHexString(wire), Long.toHexString(bits));
                }
                bits = wire;
            }
            checked(f, wire, bits);
            m.put("f64", String.format("0x%016x", bits));
            m.put("value", readable(x));
        }
        return m;
    }

    private IllegalStateException nanGuard(Tables.Field f, String wire, String kaitai) {
        return new IllegalStateException("NaN bit recovery for " + f.id + " at byte " + (bit / 8 - f.width)
                + " read 0x" + wire + ", Kaitai read 0x" + kaitai);
    }

    static Object readable(double v) {
        if (Double.isNaN(v)) {
            return "NaN";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "Infinity" : "-Infinity";
        }
        return v;
    }

    private void align() {
        bit = (bit + 7) & ~7L;
    }

    /** A little-endian integer at the (byte-aligned) position, which moves past it. */
    private long readInt(int width, boolean signed) {
        int at = (int) (bit / 8);
        if (at + width > buf.length) {
            throw new IllegalStateException("offset error: a " + width + "-byte field at " + at + " is past the input");
        }
        long v = 0;
        for (int i = width - 1; i >= 0; i--) {
            v = v << 8 | (buf[at + i] & 0xFF);
        }
        if (signed && width < 8) {
            long sign = 1L << (8 * width - 1);
            v = (v ^ sign) - sign;
        }
        bit += 8L * width;
        return v;
    }

    /** `n` bits in little-endian bit order (least significant bit of each byte first). */
    private long readBits(int n) {
        if (bit + n > 8L * buf.length) {
            throw new IllegalStateException("offset error: " + n + " bits at bit " + bit + " are past the input");
        }
        long v = 0;
        for (int i = 0; i < n; i++) {
            long b = bit + i;
            v |= (long) ((buf[(int) (b >>> 3)] >>> (b & 7)) & 1) << i;
        }
        bit += n;
        return v;
    }
}
