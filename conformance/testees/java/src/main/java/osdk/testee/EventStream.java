package osdk.testee;

import java.util.Map;
import java.util.function.Consumer;
import osdk_kaitai.Deframer;

/**
 * The loop of decode_stream: each read through the library's Deframer and the
 * StreamDecoder, each event to a consumer. The bench mode runs the same
 * loop without value models.
 */
final class EventStream {
    private final Deframer deframer = new Deframer();
    private final StreamDecoder decoder;
    private final Consumer<Map<String, Object>> onEvent;

    EventStream(String profile, boolean models, Consumer<Map<String, Object>> onEvent) {
        this.decoder = new StreamDecoder(profile, models);
        this.onEvent = onEvent;
    }

    /** The first n bytes of chunk (not kept). */
    void feed(byte[] chunk, int n) {
        for (Deframer.Event ev : deframer.feed(chunk, 0, n)) {
            onEvent.accept(decoder.event(ev));
        }
    }

    void finish() {
        for (Deframer.Event ev : deframer.finish()) {
            onEvent.accept(decoder.event(ev));
        }
    }
}
