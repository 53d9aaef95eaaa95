package osdk.testee;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import io.kaitai.struct.KaitaiStruct;
import osdk_kaitai.Deframer;
import osdk_kaitai.Osdk;
import osdk_kaitai.OsdkException;
import osdk_kaitai.OsdkFrame;

/**
 * The events of one decode_stream: the library's Deframer and decodeFrame /
 * decodePayload, and ACK matching. An ACK's value is typed by the
 * command with the same session and SEQ seen earlier in the stream; at most
 * PENDING_LIMIT unanswered commands are remembered, the oldest forgotten
 * first. Without models, values stay as the parsers returned them (the
 * bench mode times decoding, not the value model).
 */
final class StreamDecoder {
    static final int PENDING_LIMIT = 1024;

    private final String profile;
    private final boolean models;
    // (session, seq) -> (cmd_set, cmd_id), in the order first seen
    private final Map<Long, int[]> pending = new LinkedHashMap<>();

    StreamDecoder(String profile, boolean models) {
        this.profile = profile;
        this.models = models;
    }

    Map<String, Object> event(Deframer.Event ev) {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("offset", ev.offset());
        switch (ev.kind()) {
            case GARBAGE:
                out.put("kind", "garbage");
                out.put("length", (long) ev.length());
                return out;
            case ERROR:
                return error(ev, ev.errorClass(), ev.detail());
            default:
                try {
                    return frame(ev);
                } catch (OsdkException r) {
                    return error(ev, r.errorClass(), r.detail());
                } catch (RuntimeException e) { // our bug must not cost the rest of the stream
                    return error(ev, "undecodable", "internal error (" + e.getClass().getSimpleName() + ": "
                            + Main.oneLine(e.getMessage()) + ")");
                }
        }
    }

    private Map<String, Object> frame(Deframer.Event ev) {
        OsdkFrame f = Osdk.decodeFrame(ev.raw(), profile);
        Map<String, Object> model = models ? ValueModel.of(f, ev.raw()) : null;
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("offset", ev.offset());
        out.put("kind", "frame");
        OsdkFrame.FrameData data = Osdk.frameData(f);
        if (data != null) {
            long key = f.session() << 16 | f.seq();
            if (f.isAck()) {
                int[] cmd = pending.remove(key);
                if (cmd != null) {
                    String ackOf = Osdk.commandName(cmd[0], cmd[1]);
                    out.put("ack_of", ackOf);
                    byte[] value = data.ackValue();
                    KaitaiStruct ack;
                    try {
                        ack = Osdk.decodePayload(value, cmd[0], cmd[1], true, profile);
                    } catch (OsdkException r) {
                        Map<String, Object> err = error(ev, r.errorClass(), r.detail());
                        err.put("ack_of", ackOf);
                        return err;
                    }
                    out.put("ack", models ? ValueModel.of(ack, value) : ack);
                }
            } else if (f.session() > 0) {
                // cmd_set_code: the number, also for a command set the spec has no name for
                pending.put(key, new int[] {data.cmdSetCode(), data.cmdId()});
                if (pending.size() > PENDING_LIMIT) {
                    Iterator<Long> oldest = pending.keySet().iterator();
                    oldest.next();
                    oldest.remove();
                }
            }
        }
        out.put("frame", models ? model : f);
        return out;
    }

    private static Map<String, Object> error(Deframer.Event ev, String cls, String detail) {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("offset", ev.offset());
        out.put("kind", "error");
        out.put("error", cls);
        out.put("detail", detail);
        out.put("length", (long) ev.length());
        return out;
    }
}
