/* The receiver: garbage, resynchronisation after bad headers and bad CRC-32s,
 * truncated tails, and events that do not depend on chunking. */
#include <string.h>

#include "check.h"
#include "osdk_crc.h"
#include "osdk_deframer.h"

#define MAX_EVENTS 64

typedef struct {
    int kind;
    unsigned long offset;
    unsigned long length;
    int error;
} ev_t;

typedef struct {
    ev_t ev[MAX_EVENTS];
    int n;
} log_t;

static void record(void *user, const osdk_event_t *e)
{
    log_t *l = user;
    if (l->n < MAX_EVENTS) {
        l->ev[l->n].kind = (int)e->kind;
        l->ev[l->n].offset = (unsigned long)e->offset;
        l->ev[l->n].length = (unsigned long)e->length;
        l->ev[l->n].error = e->kind == OSDK_EVENT_ERROR ? (int)e->error : 0;
    }
    l->n++;
}

static uint8_t window[OSDK_DEFRAMER_MIN_BUFFER];

/* Feed data in pieces of `step` bytes (0: all at once). */
static void run(const unsigned char *data, size_t len, size_t step, log_t *l)
{
    osdk_deframer_t d;
    size_t pos = 0;
    memset(l, 0, sizeof *l);
    CHECK(osdk_deframer_init(&d, window, sizeof window));
    if (step == 0) step = len ? len : 1;
    while (pos < len) {
        size_t k = len - pos < step ? len - pos : step;
        osdk_deframer_feed(&d, data + pos, k, record, l);
        pos += k;
    }
    osdk_deframer_finish(&d, record, l);
}

static void same_for_all_chunkings(const unsigned char *data, size_t len)
{
    log_t whole, piece;
    size_t step;
    run(data, len, 0, &whole);
    for (step = 1; step <= 40; step += 3) {
        run(data, len, step, &piece);
        CHECK_EQ(piece.n, whole.n);
        CHECK(memcmp(piece.ev, whole.ev, sizeof whole.ev) == 0);
    }
}

static const char *MOVEMENT = "aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba";
static const char *BROADCAST = "aa1600000000000007001ede02000018035769c676b2";

int main(void)
{
    unsigned char buf[512];
    size_t n, m;
    log_t l;
    uint8_t small[16];
    osdk_deframer_t d;

    CHECK(!osdk_deframer_init(&d, small, sizeof small));

    /* garbage, a frame, garbage, a frame */
    n = unhex("0102", buf);
    n += unhex(MOVEMENT, buf + n);
    n += unhex("ffee", buf + n);
    m = n;
    n += unhex(BROADCAST, buf + n);
    run(buf, n, 0, &l);
    CHECK_EQ(l.n, 4);
    CHECK_EQ(l.ev[0].kind, OSDK_EVENT_GARBAGE);
    CHECK_EQ(l.ev[0].offset, 0);
    CHECK_EQ(l.ev[0].length, 2);
    CHECK_EQ(l.ev[1].kind, OSDK_EVENT_FRAME);
    CHECK_EQ(l.ev[1].offset, 2);
    CHECK_EQ(l.ev[1].length, 35);
    CHECK_EQ(l.ev[2].kind, OSDK_EVENT_GARBAGE);
    CHECK_EQ(l.ev[2].offset, 37);
    CHECK_EQ(l.ev[3].kind, OSDK_EVENT_FRAME);
    CHECK_EQ(l.ev[3].offset, m);
    same_for_all_chunkings(buf, n);

    /* a start byte whose header fails CRC-16: one byte dropped, then the real frame */
    n = unhex("aa", buf);
    n += unhex(MOVEMENT, buf + n);
    run(buf, n, 0, &l);
    CHECK_EQ(l.n, 2);
    CHECK_EQ(l.ev[0].kind, OSDK_EVENT_ERROR);
    CHECK_EQ(l.ev[0].error, OSDK_ERR_BAD_CRC16);
    CHECK_EQ(l.ev[0].length, 1);
    CHECK_EQ(l.ev[1].kind, OSDK_EVENT_FRAME);
    CHECK_EQ(l.ev[1].offset, 1);
    same_for_all_chunkings(buf, n);

    /* a frame with a bad CRC-32 that hides a valid frame: rescan after its start byte */
    n = unhex("aa3000000000000001009bd0", buf); /* header of a 48-byte frame, its CRC-16 fixed below */
    {
        uint16_t c = osdk_crc16(buf, 10);
        buf[10] = (uint8_t)c;
        buf[11] = (uint8_t)(c >> 8);
    }
    n += unhex(BROADCAST, buf + n);
    while (n < 48) buf[n++] = 0x55;
    run(buf, n, 0, &l);
    CHECK(l.n >= 2);
    CHECK_EQ(l.ev[0].kind, OSDK_EVENT_ERROR);
    CHECK_EQ(l.ev[0].error, OSDK_ERR_BAD_CRC32);
    CHECK_EQ(l.ev[0].length, 48);
    CHECK_EQ(l.ev[1].kind, OSDK_EVENT_GARBAGE);
    CHECK_EQ(l.ev[1].offset, 1);
    CHECK_EQ(l.ev[2].kind, OSDK_EVENT_FRAME);
    CHECK_EQ(l.ev[2].offset, 12);
    CHECK_EQ(l.ev[3].kind, OSDK_EVENT_GARBAGE);
    same_for_all_chunkings(buf, n);

    /* a version error: VER = 1, CRC-16 fixed so VER is what fails */
    n = unhex(MOVEMENT, buf);
    buf[2] |= 0x04;
    {
        uint16_t c = osdk_crc16(buf, 10);
        buf[10] = (uint8_t)c;
        buf[11] = (uint8_t)(c >> 8);
    }
    CHECK_EQ(osdk_frame_header_problem(buf, NULL, 0), OSDK_ERR_BAD_VERSION);

    /* truncated tail: the input ends inside a frame */
    n = unhex(MOVEMENT, buf);
    run(buf, 20, 0, &l);
    CHECK_EQ(l.ev[0].kind, OSDK_EVENT_ERROR);
    CHECK_EQ(l.ev[0].error, OSDK_ERR_TRUNCATED_FRAME);
    CHECK_EQ(l.ev[0].offset, 0);
    CHECK_EQ(l.ev[0].length, 20);
    CHECK_EQ(l.ev[1].kind, OSDK_EVENT_GARBAGE);
    CHECK_EQ(l.ev[1].offset, 1);
    CHECK_EQ(l.ev[1].length, 19);
    same_for_all_chunkings(buf, 20);

    /* a lone start byte at the end */
    run((const unsigned char *)"\xaa", 1, 0, &l);
    CHECK_EQ(l.n, 1);
    CHECK_EQ(l.ev[0].error, OSDK_ERR_TRUNCATED_FRAME);
    CHECK_EQ(l.ev[0].length, 1);

    /* decode_frame's checks */
    n = unhex(MOVEMENT, buf);
    CHECK_EQ(osdk_frame_problem(buf, 0, NULL, 0), OSDK_ERR_TRUNCATED_FRAME);
    CHECK_EQ(osdk_frame_problem(buf + 1, n - 1, NULL, 0), OSDK_ERR_BAD_SOF);
    CHECK_EQ(osdk_frame_problem(buf, 11, NULL, 0), OSDK_ERR_TRUNCATED_FRAME);
    CHECK_EQ(osdk_frame_problem(buf, n - 1, NULL, 0), OSDK_ERR_TRUNCATED_FRAME);
    buf[n] = 0;
    CHECK_EQ(osdk_frame_problem(buf, n + 1, NULL, 0), OSDK_ERR_LENGTH_MISMATCH);

    /* a long run of start bytes and noise never overflows the window */
    {
        static unsigned char noise[5000];
        size_t i;
        for (i = 0; i < sizeof noise; i++) noise[i] = (unsigned char)(i % 3 ? 0xaa : (i * 37) & 0xff);
        run(noise, sizeof noise, 0, &l);
        CHECK(l.n > 0);
        run(noise, sizeof noise, 7, &l);
        CHECK(l.n > 0);
    }
    return check_done("test_deframer");
}
