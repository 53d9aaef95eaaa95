package osdk.testee;

import java.util.LinkedHashMap;
import java.util.Map;
import io.kaitai.struct.KaitaiStruct;
import osdk_kaitai.Deframer;
import osdk_kaitai.Osdk;
import osdk_kaitai.OsdkException;
import osdk_kaitai.OsdkFrame;

/**
 * The events of one decode_stream: the library's Deframer and decodeFrame /
 * decodePayload, and ACK matching (PROTOCOL.md "ACK matching", ERRATA E32):
 * one slot per session 2..31; a plain command takes its session's slot, and
 * an ACK in that session with the slot's SEQ (a header-only one too) is typed
 * by that command and empties the slot. Sessions 0 and 1 have no slot.
 * Without models, values stay as the parsers returned them (the
 * bench mode times decoding, not the value model).
 */
final class StreamDecoder {
    static final int FIRST_ACK_SESSION = 2;
    static final int LAST_ACK_SESSION = 31;

    private final String profile;
    private final boolean models;
    // by session: {seq, cmd_set, cmd_id} of the command waiting for its ACK, or null
    private final int[][] slots = new int[LAST_ACK_SESSION + 1][];

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
        boolean headerOnly = f.len() == 12;
        boolean hasSlot = f.session() >= FIRST_ACK_SESSION && f.session() <= LAST_ACK_SESSION;
        if (f.isAck() && (data != null || headerOnly) && hasSlot) {
            int[] cmd = slots[(int) f.session()];
            if (cmd != null && cmd[0] == f.seq()) {
                slots[(int) f.session()] = null;
                String ackOf = Osdk.commandName(cmd[1], cmd[2]);
                out.put("ack_of", ackOf);
                byte[] value = data != null ? data.ackValue() : new byte[0]; // a header-only ACK's value is empty
                KaitaiStruct ack;
                try {
                    ack = Osdk.decodePayload(value, cmd[1], cmd[2], true, profile);
                } catch (OsdkException r) {
                    Map<String, Object> err = error(ev, r.errorClass(), r.detail());
                    err.put("ack_of", ackOf);
                    return err;
                }
                out.put("ack", models ? ValueModel.of(ack, value) : ack);
            }
        } else if (!f.isAck() && data != null && hasSlot) {
            // cmd_set_code: the number, also for a command set the spec has no name for
            slots[(int) f.session()] = new int[] {f.seq(), data.cmdSetCode(), data.cmdId()};
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
