package osdk_examples;

import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import osdk_kaitai.Command;
import osdk_kaitai.Osdk;

/** `send`: one frame of each command an onboard computer sends, as NAME HEX. */
public final class Send {
    private Send() {
    }

    public static void run(PrintStream out) {
        byte[] bundleId = "0123456789abcdef0123456789abcdef".getBytes(StandardCharsets.US_ASCII);
        int[] codes = {1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 0, 0};
        print(out, Command.VERSION_QUERY, 2, 1, Osdk.encodeVersionQuery(0));
        print(out, Command.ACTIVATION, 2, 2, Osdk.encodeActivation(1000001, 2, 0x03016400, bundleId));
        print(out, Command.SET_FREQUENCY, 2, 3, Osdk.encodeSetFrequency(codes));
        print(out, Command.CONTROL_AUTHORITY, 2, 4, Osdk.encodeControlAuthority(1));
        // mode 0x4B: horizontal velocity, vertical velocity, yaw rate, body frame, stable
        byte[] move = Osdk.encodeMovementControl(0x4B, 1.0f, -2.0f, 0.5f, 30.0f);
        print(out, Command.MOVEMENT_CONTROL, 0, 0x1234, move);
    }

    private static void print(PrintStream out, Command command, int session, int seq, byte[] value) {
        byte[] frame = Osdk.encodeFrame(command, session, seq, value);
        out.println(command.specName() + " " + Hex.of(frame));
    }
}
