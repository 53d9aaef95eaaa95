package osdk.testee;

import java.io.BufferedOutputStream;
import java.io.BufferedReader;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The request loop of conformance/PROTOCOL.md (osdk_conformance/harness/serve.py):
 * one JSON line in, one JSON line out, flushed. Input the testee cannot use
 * is answered `bad_request`, a bug of its own `internal_error`: a failed
 * case, never a dead testee.
 */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length > 0) { // --bench FILE --profile P (Bench.java)
            System.exit(Bench.main(args));
        }
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        OutputStream out = new BufferedOutputStream(new FileOutputStream(FileDescriptor.out), 1 << 16);
        String line;
        while ((line = in.readLine()) != null) {
            if (line.isBlank()) {
                continue;
            }
            out.write(respond(line).getBytes(StandardCharsets.UTF_8));
            out.write('\n');
            out.flush();
        }
    }

    @SuppressWarnings("unchecked")
    static String respond(String line) {
        Map<String, Object> res;
        try {
            Object req = Json.parse(line);
            if (!(req instanceof Map) || !(((Map<String, Object>) req).get("op") instanceof String)) {
                throw new BadRequest("a request is a JSON object with an \"op\" string");
            }
            res = Operations.answer((Map<String, Object>) req);
        } catch (BadRequest | Json.ParseError | StackOverflowError e) { // bad requests, JSON that does not parse
            res = failure("bad_request", e);
        } catch (Throwable e) { // a bug of ours
            res = failure("internal_error", e);
        }
        try {
            return Json.write(res);
        } catch (RuntimeException e) {
            return Json.write(failure("internal_error", e));
        }
    }

    static String oneLine(String s) {
        return s == null ? "" : s.replaceAll("\\s+", " ").trim();
    }

    private static Map<String, Object> failure(String cls, Throwable e) {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("ok", false);
        out.put("error", cls);
        out.put("detail", e.getClass().getSimpleName() + ": " + oneLine(e.getMessage()));
        return out;
    }
}
