/*
 * baseline.c - the yardstick of `osdkc bench`: a receiver in the manner of
 * the DJI Onboard SDK's, written for this kit.
 *
 * Byte by byte: hunt for the start byte, collect the 12-byte header, check
 * its CRC-16 (and the fields the SDK's header check looks at), collect LEN
 * bytes, check the CRC-32; after a failed check drop the start byte and
 * rescan what followed it. A good frame is then handled as the SDK does:
 * the broadcast's items are memcpy'd into a packed struct, one after the
 * other as the flag word announces them, with no check that the payload
 * holds them, no range checks and no validation; a command's value and a
 * matched ACK's value are memcpy'd likewise. This is the least work a
 * receiver can do, which is what the generated, fully checked decoder is
 * measured against.
 *
 * The struct of the latest item values and each profile's item slots and
 * sizes come from build/items.h (generated from the spec by gen_items.py);
 * the CRCs are generated/c/osdk_crc.c, the same code the generated decoder
 * uses.
 *
 *   osdk-baseline --bench FILE|- --profile P     (conformance/PROTOCOL.md, "Bench mode")
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "items.h"
#include "osdk_crc.h"

#define SOF 0xAAu
#define HEADER_LEN 12u
#define CRC32_LEN 4u
#define MAX_FRAME 1023u
#define READ_SIZE (64u * 1024u)
#define USAGE "usage: --bench FILE|- --profile P"

/* Not static: the copies are the work being measured and must not be optimised away. */
broadcast_t baseline_broadcast;
uint8_t baseline_command[MAX_FRAME];
uint8_t baseline_ack[MAX_FRAME];

/* ---- the receiver ------------------------------------------------------------------ */

typedef struct {
    uint8_t win[MAX_FRAME + 1]; /* win[0 .. fill) is the frame so far, win[fill .. avail) waits to be rescanned */
    size_t fill, avail, len;
    unsigned items;
    uint8_t *dest[MAX_ITEMS];
    unsigned size[MAX_ITEMS];
    uint16_t pending_seq[32]; /* per session: SEQ of the last command, to match its ACK */
    uint8_t pending[32];
    unsigned long long frames, errors, garbage_bytes;
} rx_t;

static unsigned le16(const uint8_t *p) { return (unsigned)p[0] | (unsigned)p[1] << 8; }

static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static int header_ok(const uint8_t *h)
{
    unsigned word = le16(h + 1), len = word & 0x3FFu;
    if (osdk_crc16(h, 10) != le16(h + 10)) return 0;
    if (word >> 10 || h[3] >> 6 || h[5] || h[6] || h[7]) return 0; /* version, reserved */
    return len == HEADER_LEN || len > HEADER_LEN + CRC32_LEN;
}

static void handle(rx_t *rx, const uint8_t *f, size_t len)
{
    const uint8_t *data = f + HEADER_LEN;
    unsigned session = f[3] & 0x1Fu, seq = le16(f + 8);
    size_t n = len > HEADER_LEN ? len - HEADER_LEN - CRC32_LEN : 0;
    if (!n) return;
    if (f[3] & 0x20u) { /* ACK */
        if (rx->pending[session] && rx->pending_seq[session] == seq) {
            rx->pending[session] = 0;
            memcpy(baseline_ack, data, n);
        }
        return;
    }
    if (data[0] == 0x02 && data[1] == 0x00) { /* flight data broadcast */
        const uint8_t *p = data + 4;
        unsigned flags = le16(data + 2), i;
        for (i = 0; i < rx->items; i++) {
            if (flags >> i & 1u) {
                memcpy(rx->dest[i], p, rx->size[i]);
                p += rx->size[i];
            }
        }
        return;
    }
    if (n >= 2) memcpy(baseline_command, data + 2, n - 2);
    if (session) {
        rx->pending[session] = 1;
        rx->pending_seq[session] = (uint16_t)seq;
    }
}

/* The start byte was wrong after all: forget it, rescan what followed. */
static void drop_first(rx_t *rx)
{
    memmove(rx->win, rx->win + 1, rx->avail - 1);
    rx->avail--;
    rx->fill = 0;
}

static void run(rx_t *rx)
{
    while (rx->fill < rx->avail) {
        if (rx->fill == 0 && rx->win[0] != SOF) {
            rx->garbage_bytes++;
            drop_first(rx);
            continue;
        }
        rx->fill++;
        if (rx->fill == HEADER_LEN) {
            if (!header_ok(rx->win)) {
                rx->errors++;
                drop_first(rx);
                continue;
            }
            rx->len = le16(rx->win + 1) & 0x3FFu;
        }
        if (rx->fill >= HEADER_LEN && rx->fill == rx->len) {
            if (rx->len > HEADER_LEN &&
                osdk_crc32(rx->win, rx->len - CRC32_LEN) != le32(rx->win + rx->len - CRC32_LEN)) {
                rx->errors++;
                drop_first(rx);
                continue;
            }
            rx->frames++;
            handle(rx, rx->win, rx->len);
            memmove(rx->win, rx->win + rx->len, rx->avail - rx->len);
            rx->avail -= rx->len;
            rx->fill = 0;
        }
    }
}

static void feed(rx_t *rx, const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        rx->win[rx->avail++] = p[i];
        run(rx);
    }
}

/* End of input: a started frame cannot complete; rescan after its start byte. */
static void finish(rx_t *rx)
{
    while (rx->avail) {
        rx->errors++;
        drop_first(rx);
        run(rx);
    }
}

/* ---- bench mode ------------------------------------------------------------------------ */

static int fail(const char *fmt, const char *a, const char *b)
{
    fputs("osdk-baseline --bench: ", stderr);
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    return 2;
}

static void setup(rx_t *rx, int profile)
{
    unsigned i;
    rx->items = ITEM_COUNT[profile];
    for (i = 0; i < rx->items; i++) {
        rx->dest[i] = (uint8_t *)&baseline_broadcast + ITEM_OFFSETS[profile][i];
        rx->size[i] = ITEM_SIZES[profile][i];
    }
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

int main(int argc, char **argv)
{
    static uint8_t chunk[READ_SIZE];
    static rx_t rx;
    const char *path = NULL, *profile_id = NULL;
    unsigned long long total = 0;
    int i, profile = -1;
    size_t n;
    double start, seconds;
    FILE *in;
    for (i = 1; i < argc; i += 2) {
        const char **slot = strcmp(argv[i], "--bench") == 0     ? &path
                            : strcmp(argv[i], "--profile") == 0 ? &profile_id
                                                                : NULL;
        if (!slot) return fail("unknown argument '%s'; %s", argv[i], USAGE);
        if (i + 1 >= argc) return fail("%s needs a value; %s", argv[i], USAGE);
        if (*slot) return fail("%s given twice; %s", argv[i], USAGE);
        *slot = argv[i + 1];
    }
    if (!path || !profile_id) return fail("%s%s", USAGE, "");
    for (i = 0; i < PROFILE_COUNT; i++) {
        if (strcmp(profile_id, PROFILE_IDS[i]) == 0) profile = i;
    }
    if (profile < 0) {
        char known[128] = "";
        for (i = 0; i < PROFILE_COUNT; i++) {
            if (i) strncat(known, ", ", sizeof known - strlen(known) - 1);
            strncat(known, PROFILE_IDS[i], sizeof known - strlen(known) - 1);
        }
        return fail("unknown profile '%s' (known: %s)", profile_id, known);
    }
    setup(&rx, profile);
    in = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    if (!in) return fail("cannot read %s: %s", path, strerror(errno));
    start = now();
    while ((n = fread(chunk, 1, sizeof chunk, in)) > 0) {
        total += n;
        feed(&rx, chunk, n);
    }
    if (ferror(in)) return fail("cannot read %s: %s", path, strerror(errno));
    finish(&rx);
    seconds = now() - start;
    if (in != stdin) fclose(in);
    printf("{\"impl\": \"baseline\", \"profile\": \"%s\", \"bytes\": %llu, \"frames\": %llu, \"errors\": %llu, "
           "\"garbage_bytes\": %llu, \"seconds\": %.6f}\n",
           PROFILE_IDS[profile], total, rx.frames, rx.errors, rx.garbage_bytes, seconds);
    return fflush(stdout) == 0 ? 0 : 2;
}
