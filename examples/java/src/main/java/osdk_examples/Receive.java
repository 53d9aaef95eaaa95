package osdk_examples;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import osdk_kaitai.Broadcast;
import osdk_kaitai.Deframer;
import osdk_kaitai.Osdk;
import osdk_kaitai.OsdkException;
import osdk_kaitai.OsdkFrame;

/** `receive PROFILE`: the frames of a byte stream on standard input, one line per event. */
public final class Receive {
    private Receive() {
    }

    public static void run(String profile, InputStream in, PrintStream out) throws IOException {
        Deframer deframer = new Deframer();
        byte[] buf = new byte[4096];
        for (int n; (n = in.read(buf)) >= 0;) {
            for (Deframer.Event e : deframer.feed(buf, 0, n)) {
                print(e, profile, out);
            }
        }
        for (Deframer.Event e : deframer.finish()) {
            print(e, profile, out);
        }
    }

    private static void print(Deframer.Event e, String profile, PrintStream out) {
        switch (e.kind()) {
            case GARBAGE:
                out.println("garbage " + e.offset() + " " + e.length());
                return;
            case ERROR:
                out.println("error " + e.offset() + " " + e.length() + " " + e.errorClass());
                return;
            default:
                break;
        }
        OsdkFrame frame;
        try {
            frame = Osdk.decodeFrame(e.raw(), profile);
        } catch (OsdkException x) { // x.field() names the field that failed
            out.println("error " + e.offset() + " " + e.length() + " " + x.errorClass());
            return;
        }
        OsdkFrame.FrameData data = Osdk.frameData(frame);
        if (data == null) {
            out.println("empty " + e.offset() + " " + frame.seq());
        } else if (frame.isAck()) {
            out.println("ack " + e.offset() + " " + frame.seq());
        } else {
            out.println("frame " + e.offset() + " " + frame.seq() + " " + data.cmdSetCode() + " " + data.cmdId());
            Broadcast bc = Osdk.broadcastOf(frame);
            if (bc != null) {
                for (String item : Broadcast.items(profile)) {
                    out.println("  " + item + " " + describe(bc, item));
                }
            }
        }
    }

    // an absent item is null: its flag bit is clear (or the profile has no such item)
    private static String describe(Broadcast bc, String item) {
        if (bc.item(item) == null) {
            return "absent";
        }
        if (item.equals("battery")) {
            return Integer.toString(bc.battery());
        }
        if (item.equals("time_stamp")) {
            return Long.toString(bc.timeStamp().time());
        }
        return "present";
    }
}
