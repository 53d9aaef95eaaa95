package osdk.testee;

import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The bench mode (conformance/PROTOCOL.md): {@code --bench FILE --profile P}
 * runs FILE (standard input for {@code -}) in reads of at most 64 KiB through
 * decode_stream's own loop (EventStream) without value models, keeps only
 * counters, and prints one JSON line with the counts and the seconds of the
 * loop. Bad arguments or unreadable input: one stderr line, exit 2.
 */
final class Bench {
    static final String IMPL = "java";
    static final int READ_SIZE = 64 * 1024;
    static final String USAGE = "usage: --bench FILE|- --profile P";

    /** Bad arguments or unreadable input. */
    static final class Failure extends Exception {
        private static final long serialVersionUID = 1L;

        Failure(String message) {
            super(message);
        }
    }

    private Bench() {
    }

    /** The exit status of the bench mode. */
    static int main(String[] args) {
        try {
            Map<String, String> opts = parseArgs(args, Tables.INSTANCE.profiles);
            Map<String, Object> result = new LinkedHashMap<>();
            result.put("impl", IMPL);
            result.putAll(run(opts.get("--bench"), opts.get("--profile")));
            System.out.println(Json.write(result));
            return 0;
        } catch (Failure f) {
            System.err.println(IMPL + " --bench: " + f.getMessage());
            return 2;
        }
    }

    /** `--bench FILE --profile P`, in either order. */
    static Map<String, String> parseArgs(String[] args, List<String> profiles) throws Failure {
        Map<String, String> opts = new HashMap<>();
        for (int i = 0; i < args.length; i += 2) {
            String key = args[i];
            if (!key.equals("--bench") && !key.equals("--profile")) {
                throw new Failure("unknown argument '" + key + "'; " + USAGE);
            }
            if (i + 1 >= args.length) {
                throw new Failure(key + " needs a value; " + USAGE);
            }
            if (opts.put(key, args[i + 1]) != null) {
                throw new Failure(key + " given twice; " + USAGE);
            }
        }
        if (!opts.containsKey("--bench") || !opts.containsKey("--profile")) {
            throw new Failure(USAGE);
        }
        if (!profiles.contains(opts.get("--profile"))) {
            throw new Failure("unknown profile '" + opts.get("--profile") + "' (known: "
                    + String.join(", ", profiles) + ")");
        }
        return opts;
    }

    private static Map<String, Object> run(String path, String profile) throws Failure {
        long[] counts = new long[3]; // frames, errors, garbage bytes
        EventStream stream = new EventStream(profile, false, ev -> {
            Object kind = ev.get("kind");
            if (kind.equals("frame")) {
                counts[0]++;
            } else if (kind.equals("error")) {
                counts[1]++;
            } else {
                counts[2] += (Long) ev.get("length");
            }
        });
        long bytes = 0;
        long start;
        long end;
        // The deframer copies what it keeps, so one read buffer serves every read.
        byte[] buf = new byte[READ_SIZE];
        try (InputStream in = path.equals("-") ? System.in : new FileInputStream(path)) {
            start = System.nanoTime(); // monotonic
            for (int n; (n = in.read(buf, 0, READ_SIZE)) >= 0;) {
                bytes += n;
                stream.feed(buf, n);
            }
            stream.finish();
            end = System.nanoTime();
        } catch (IOException e) {
            throw new Failure("cannot read " + path + ": " + Main.oneLine(e.getMessage()));
        }
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("profile", profile);
        out.put("bytes", bytes);
        out.put("frames", counts[0]);
        out.put("errors", counts[1]);
        out.put("garbage_bytes", counts[2]);
        out.put("seconds", Math.round((end - start) / 1e3) / 1e6);
        return out;
    }
}
