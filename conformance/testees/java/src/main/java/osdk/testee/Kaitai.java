package osdk.testee;

import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStream;
import java.lang.reflect.Field;
import java.nio.BufferUnderflowException;
import java.util.List;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Runs a generated parser and turns what the Kaitai Java runtime throws into
 * an error class (docs/VALUE-MODEL.md):
 *
 * - a failed `valid` (ValidationFailedError) names its field by src_path
 *   "/seq/N" in the type whose _read threw it, which is the first generated
 *   class on the exception's stack; the tables give that type's seq, and
 *   `error_by_field` the class (unlisted fields are undecodable);
 * - running out of bytes (the runtime's ByteBuffer underflows) is
 *   truncated_payload;
 * - any other Kaitai error is undecodable.
 */
final class Kaitai {
    private static final String GENERATED_PACKAGE = "osdk_kaitai.";
    private static final Pattern SEQ_PATH = Pattern.compile("/seq/(\\d+)$");
    private static final Field SRC_PATH = srcPathField();

    private Kaitai() {
    }

    static <T> T parse(Function<KaitaiStream, T> make, byte[] data) throws Rejection {
        try {
            return make.apply(new ByteBufferKaitaiStream(data));
        } catch (KaitaiStream.ValidationFailedError e) {
            String field = raisingField(e);
            String cls = field == null ? "undecodable" : Tables.INSTANCE.errorByField.getOrDefault(field, "undecodable");
            throw new Rejection(cls, (field != null ? field : srcPath(e)) + ": " + oneLine(e.getMessage()));
        } catch (BufferUnderflowException e) {
            throw new Rejection("truncated_payload", "the input ended inside the value");
        } catch (KaitaiStream.KaitaiStructError e) {
            throw new Rejection("undecodable", e.getClass().getSimpleName() + ": " + oneLine(e.getMessage()));
        }
    }

    /** The ksy id of the field whose `valid` check threw `e`, or null. */
    private static String raisingField(KaitaiStream.ValidationFailedError e) {
        Matcher m = SEQ_PATH.matcher(srcPath(e));
        if (!m.find()) {
            return null;
        }
        for (StackTraceElement frame : e.getStackTrace()) {
            if (frame.getClassName().startsWith(GENERATED_PACKAGE)) {
                Class<?> cls;
                try {
                    cls = Class.forName(frame.getClassName(), false, Kaitai.class.getClassLoader());
                } catch (ClassNotFoundException x) {
                    return null;
                }
                List<String> seq = Tables.INSTANCE.typeOf(cls).seq;
                int n = Integer.parseInt(m.group(1));
                return n < seq.size() ? seq.get(n) : null;
            }
        }
        return null;
    }

    // The runtime keeps src_path in a protected field and puts it at the
    // head of the message ("/seq/7: at pos 5: validation failed: ...").
    private static String srcPath(KaitaiStream.KaitaiStructError e) {
        if (SRC_PATH != null) {
            try {
                Object v = SRC_PATH.get(e);
                if (v instanceof String) {
                    return (String) v;
                }
            } catch (IllegalAccessException ignored) {
                // fall back to the message
            }
        }
        String msg = e.getMessage() == null ? "" : e.getMessage();
        int colon = msg.indexOf(':');
        return colon < 0 ? msg : msg.substring(0, colon);
    }

    private static Field srcPathField() {
        try {
            Field f = KaitaiStream.KaitaiStructError.class.getDeclaredField("srcPath");
            f.setAccessible(true);
            return f;
        } catch (ReflectiveOperationException | RuntimeException e) {
            return null;
        }
    }

    static String oneLine(String s) {
        return s == null ? "" : s.replaceAll("\\s+", " ").trim();
    }
}
