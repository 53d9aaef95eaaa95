package osdk_examples;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashSet;
import java.util.Set;
import osdk_kaitai.Broadcast;
import osdk_kaitai.Osdk;
import osdk_kaitai.OsdkException;
import osdk_kaitai.OsdkFrame;

/**
 * `check`: not an example, the edge cases tests/test_lib_java.py compares
 * with the reference, one request line in, one answer line out:
 *
 *   movement MODE XBITS YBITS ZBITS YAWBITS   -> HEX(bits) HEX(floats)
 *   frame CMD_SET CMD_ID IS_ACK SESSION SEQ VALUE  -> HEX | error CLASS FIELD
 *   decode PROFILE HEX                        -> ok | error CLASS FIELD
 *   payload PROFILE CMD_SET CMD_ID IS_ACK HEX -> ok | error CLASS FIELD
 *   items PROFILE HEX                         -> ITEM=null|set ... (every item of any profile)
 *
 * Numbers are hex; "-" is an empty value. An IllegalArgumentException is "argument".
 */
public final class Check {
    // every item of any profile, the first profile's order first
    private static final Set<String> ALL_ITEMS = new LinkedHashSet<>();

    static {
        for (String profile : Osdk.PROFILES) {
            ALL_ITEMS.addAll(Broadcast.items(profile));
        }
    }

    private Check() {
    }

    public static void run(PrintStream out) throws IOException {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.US_ASCII));
        for (String line; (line = in.readLine()) != null;) {
            String[] a = line.trim().split(" ");
            try {
                out.println(answer(a));
            } catch (OsdkException e) {
                out.println("error " + e.errorClass() + " " + e.field());
            } catch (IllegalArgumentException e) {
                out.println("argument");
            }
        }
    }

    private static int num(String s) {
        return (int) Long.parseLong(s, 16);
    }

    private static String answer(String[] a) {
        switch (a[0]) {
            case "movement": {
                int mode = num(a[1]);
                int x = num(a[2]);
                int y = num(a[3]);
                int z = num(a[4]);
                int yaw = num(a[5]);
                byte[] bits = Osdk.encodeMovementControlBits(mode, x, y, z, yaw);
                byte[] floats = Osdk.encodeMovementControl(mode, Float.intBitsToFloat(x), Float.intBitsToFloat(y),
                        Float.intBitsToFloat(z), Float.intBitsToFloat(yaw));
                return Hex.of(bits) + " " + Hex.of(floats);
            }
            case "frame":
                return Hex.of(Osdk.encodeFrame(num(a[1]), num(a[2]), a[3].equals("1"), num(a[4]), num(a[5]),
                        Hex.parse(a[6])));
            case "decode":
                Osdk.decodeFrame(Hex.parse(a[2]), a[1]);
                return "ok";
            case "payload":
                Osdk.decodePayload(Hex.parse(a[5]), num(a[2]), num(a[3]), a[4].equals("1"), a[1]);
                return "ok";
            case "items": {
                OsdkFrame f = Osdk.decodeFrame(Hex.parse(a[2]), a[1]);
                Broadcast bc = Osdk.broadcastOf(f);
                if (bc == null) {
                    return "not a broadcast";
                }
                StringBuilder sb = new StringBuilder();
                for (String item : ALL_ITEMS) {
                    sb.append(item).append(bc.item(item) == null ? "=null " : "=set ");
                }
                sb.append("gps_detail()=").append(bc.gpsDetail() == null ? "null" : "set");
                return sb.toString();
            }
            default:
                throw new IllegalArgumentException("unknown check " + a[0]);
        }
    }
}
