package osdk.testee;

import java.util.ArrayList;
import java.util.List;

/**
 * Finds frames in a byte stream the way the SDK's receiver does
 * (osdk_conformance/core/deframe.py is the reference this follows step by step):
 * hunt for 0xAA; check the 12-byte header (CRC-16 first, then VER, RES0,
 * RES1, LEN) and on any failure drop that ONE byte and hunt again; with a
 * good header wait for LEN bytes and check the CRC-32, dropping one byte on
 * failure so that a frame hidden inside a corrupt one is still found.
 * Every rejection is reported. Offsets are absolute.
 */
final class Deframer {
    static final int SOF = 0xAA;
    static final int HEADER_LEN = 12;
    static final int CRC32_LEN = 4;
    static final int MAX_LEN = 0x3FF;

    /** One thing the receiver saw: a frame, a rejection or a garbage run. */
    static final class Event {
        enum Kind { FRAME, REJECTED, GARBAGE }

        final Kind kind;
        final long offset;
        final int length;
        final byte[] raw; // FRAME only
        final String error; // REJECTED only
        final String detail;

        private Event(Kind kind, long offset, int length, byte[] raw, String error, String detail) {
            this.kind = kind;
            this.offset = offset;
            this.length = length;
            this.raw = raw;
            this.error = error;
            this.detail = detail;
        }

        static Event frame(long offset, byte[] raw) {
            return new Event(Kind.FRAME, offset, raw.length, raw, null, null);
        }

        static Event rejected(long offset, Rejection r, int length) {
            return new Event(Kind.REJECTED, offset, length, null, r.cls, r.detail);
        }

        static Event garbage(long offset, int length) {
            return new Event(Kind.GARBAGE, offset, length, null, null, null);
        }
    }

    private byte[] buf = new byte[0];
    private int start; // buf[start, end) is what is still unscanned
    private int end;
    private long base; // absolute offset of buf[start]
    private long garbageStart = -1;

    List<Event> feed(byte[] chunk) {
        return feed(chunk, chunk.length);
    }

    /** The first n bytes of chunk, which is not kept: a reader can reuse it. */
    List<Event> feed(byte[] chunk, int n) {
        append(chunk, n);
        return scan(false);
    }

    List<Event> finish() {
        return scan(true);
    }

    /** The first thing wrong with a 12-byte header at data[at], or null. */
    static Rejection headerProblem(byte[] data, int at) {
        int stored = u8(data, at + 10) | u8(data, at + 11) << 8;
        long computed = Crc.CRC16.of(data, at, at + 10);
        if (computed != stored) {
            return new Rejection("bad_crc16", String.format("CRC-16 is 0x%04x, expected 0x%04x", stored, computed));
        }
        int word = u8(data, at + 1) | u8(data, at + 2) << 8;
        int length = word & 0x3FF;
        int ver = word >>> 10;
        if (ver != 0) {
            return new Rejection("bad_version", "header version " + ver + ", must be 0");
        }
        if (u8(data, at + 3) >>> 6 != 0) {
            return new Rejection("reserved_bits", "RES0 is " + (u8(data, at + 3) >>> 6) + ", must be 0");
        }
        if (data[at + 5] != 0 || data[at + 6] != 0 || data[at + 7] != 0) {
            return new Rejection("reserved_bits", String.format("RES1 is 0x%02x%02x%02x, must be 0",
                    u8(data, at + 7), u8(data, at + 6), u8(data, at + 5)));
        }
        if (length < HEADER_LEN || (HEADER_LEN < length && length <= HEADER_LEN + CRC32_LEN)) {
            return new Rejection("impossible_length", "LEN " + length + " is impossible (12, or 17 to " + MAX_LEN + ")");
        }
        return null;
    }

    static int frameLength(byte[] data, int at) {
        return (u8(data, at + 1) | u8(data, at + 2) << 8) & 0x3FF;
    }

    /** A frame with DATA carries a CRC-32 whose residue over the whole frame is 0. */
    static boolean crc32Fails(byte[] data, int at, int length) {
        return length > HEADER_LEN && Crc.CRC32.of(data, at, at + length) != 0;
    }

    private List<Event> scan(boolean fin) {
        List<Event> out = new ArrayList<>();
        while (start < end) {
            if (u8(buf, start) != SOF) {
                int next = start;
                while (next < end && u8(buf, next) != SOF) {
                    next++;
                }
                if (garbageStart < 0) {
                    garbageStart = base;
                }
                drop(next - start);
                continue;
            }
            flushGarbage(out);
            int have = end - start;
            if (have < HEADER_LEN) {
                if (!fin) {
                    break;
                }
                out.add(truncated(-1));
                continue;
            }
            Rejection problem = headerProblem(buf, start);
            if (problem != null) {
                out.add(Event.rejected(base, problem, 1));
                drop(1);
                continue;
            }
            int length = frameLength(buf, start);
            if (have < length) {
                if (!fin) {
                    break;
                }
                out.add(truncated(length));
                continue;
            }
            if (crc32Fails(buf, start, length)) {
                long stored = u8(buf, start + length - 4) | (long) u8(buf, start + length - 3) << 8
                        | (long) u8(buf, start + length - 2) << 16 | (long) u8(buf, start + length - 1) << 24;
                long expected = Crc.CRC32.of(buf, start, start + length - 4);
                out.add(Event.rejected(base, new Rejection("bad_crc32",
                        String.format("CRC-32 is 0x%08x, expected 0x%08x", stored, expected)), length));
                drop(1);
                continue;
            }
            byte[] raw = new byte[length];
            System.arraycopy(buf, start, raw, 0, length);
            out.add(Event.frame(base, raw));
            drop(length);
        }
        if (fin) {
            flushGarbage(out);
        }
        return out;
    }

    // At the end of the input a started frame can no longer complete: report
    // it, then rescan after its start byte like any rejection, so that a
    // shorter frame inside it is still found.
    private Event truncated(int length) {
        int have = end - start;
        String want = length > 0 ? "LEN " + length : "a 12-byte header";
        Event e = Event.rejected(base,
                new Rejection("truncated_frame", "input ended after " + have + " byte(s) of " + want), have);
        drop(1);
        return e;
    }

    private void flushGarbage(List<Event> out) {
        if (garbageStart >= 0) {
            out.add(Event.garbage(garbageStart, (int) (base - garbageStart)));
            garbageStart = -1;
        }
    }

    private void drop(int n) {
        start += n;
        base += n;
    }

    private void append(byte[] chunk, int n) {
        int live = end - start;
        if (buf.length - end < n) {
            // Compact, growing only when the live part itself needs it: memory
            // stays bounded by one frame plus the read size.
            byte[] next = live + n <= buf.length ? buf : new byte[Math.max(2 * buf.length, live + n)];
            System.arraycopy(buf, start, next, 0, live);
            buf = next;
            start = 0;
            end = live;
        }
        System.arraycopy(chunk, 0, buf, end, n);
        end += n;
    }

    static int u8(byte[] b, int i) {
        return b[i] & 0xFF;
    }

    /** data cut into reads of the given sizes; what they leave over is one last read. */
    static List<byte[]> splitChunks(byte[] data, List<Long> sizes) {
        List<byte[]> out = new ArrayList<>();
        int pos = 0;
        for (long size : sizes) {
            int n = (int) Math.min(size, data.length); // a longer read takes no more than all
            int from = Math.min(pos, data.length);
            int to = (int) Math.min((long) pos + n, data.length);
            out.add(java.util.Arrays.copyOfRange(data, from, to));
            pos = (int) Math.min((long) pos + n, data.length);
        }
        if (pos < data.length) {
            out.add(java.util.Arrays.copyOfRange(data, pos, data.length));
        }
        return out;
    }
}
