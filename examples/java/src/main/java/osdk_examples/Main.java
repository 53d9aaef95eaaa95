package osdk_examples;

import java.io.IOException;

/** java -jar osdk-examples.jar receive PROFILE | send */
public final class Main {
    private static final String USAGE = "usage: receive PROFILE | send";

    private Main() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length == 2 && args[0].equals("receive")) {
            try {
                osdk_kaitai.Osdk.profile(args[1]);
            } catch (IllegalArgumentException e) {
                System.err.println("receive: " + e.getMessage());
                System.exit(2);
            }
            Receive.run(args[1], System.in, System.out);
        } else if (args.length == 1 && args[0].equals("send")) {
            Send.run(System.out);
        } else if (args.length == 1 && args[0].equals("check")) {
            Check.run(System.out);
        } else {
            System.err.println(USAGE);
            System.exit(2);
        }
        System.out.flush();
    }
}
