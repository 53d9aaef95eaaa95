package osdk.testee;

/**
 * A table-driven CRC for one parameter block of the tables (`crc`). `init`
 * is the register's start value in the engine's own shift direction, as
 * the SDK code holds it, so it is never reflected here.
 */
final class Crc {
    static final Crc CRC16 = new Crc(Tables.INSTANCE.crc16);
    static final Crc CRC32 = new Crc(Tables.INSTANCE.crc32);

    private final Tables.CrcParams p;
    private final long mask;
    private final long[] table = new long[256];

    Crc(Tables.CrcParams p) {
        if (p.width < 8 || p.width > 32 || p.width % 8 != 0) {
            throw new IllegalArgumentException("CRC width " + p.width + " is not supported");
        }
        this.p = p;
        this.mask = (1L << p.width) - 1;
        if (p.reflectIn) {
            long poly = reflect(p.poly, p.width);
            for (int b = 0; b < 256; b++) {
                long reg = b;
                for (int i = 0; i < 8; i++) {
                    reg = (reg & 1) != 0 ? (reg >>> 1) ^ poly : reg >>> 1;
                }
                table[b] = reg;
            }
        } else {
            long top = 1L << (p.width - 1);
            for (int b = 0; b < 256; b++) {
                long reg = (long) b << (p.width - 8);
                for (int i = 0; i < 8; i++) {
                    reg = ((reg & top) != 0 ? (reg << 1) ^ p.poly : reg << 1) & mask;
                }
                table[b] = reg;
            }
        }
        long got = of("123456789".getBytes(java.nio.charset.StandardCharsets.US_ASCII), 0, 9);
        if (got != p.check) {
            throw new IllegalStateException(String.format("CRC-%d check value 0x%x, the tables say 0x%x", p.width, got, p.check));
        }
    }

    /** The CRC of data[from, to). */
    long of(byte[] data, int from, int to) {
        long reg = p.init & mask;
        if (p.reflectIn) {
            for (int i = from; i < to; i++) {
                reg = (reg >>> 8) ^ table[(int) ((reg ^ data[i]) & 0xFF)];
            }
        } else {
            int shift = p.width - 8;
            for (int i = from; i < to; i++) {
                reg = ((reg << 8) & mask) ^ table[(int) (((reg >>> shift) ^ data[i]) & 0xFF)];
            }
        }
        if (p.reflectOut != p.reflectIn) {
            reg = reflect(reg, p.width);
        }
        return (reg ^ p.xorout) & mask;
    }

    private static long reflect(long value, int width) {
        long out = 0;
        for (int i = 0; i < width; i++) {
            out = (out << 1) | (value & 1);
            value >>>= 1;
        }
        return out;
    }
}
