/* The edges the fuzzers cannot reach: every public entry point given no
 * buffer at all (NULL with length 0: libFuzzer always passes a pointer), and
 * the integer helpers of the header at the ends of int64_t. Built and run
 * also with clang's UBSan (`make test`), which flags NULL + 0 pointer
 * arithmetic where gcc's does not. */
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "osdk_crc.h"
#include "osdk_decoder.h"
#include "osdk_deframer.h"
#include "osdk_encode.h"

static osdk_payload_t payload;
static osdk_frame_t frame;
static osdk_broadcast_a3_fw3_1_t a3;
static osdk_broadcast_m100_fw2_3_t m23;
static osdk_broadcast_m100_fw3_1_t m31;

static int events;

static void count_event(void *user, const osdk_event_t *ev)
{
    (void)user;
    (void)ev;
    events++;
}

int main(void)
{
    osdk_error_t err;
    osdk_control_mode_t mode;
    osdk_movement_control_t move;
    osdk_deframer_t d;
    static uint8_t window[OSDK_DEFRAMER_MIN_BUFFER];
    uint8_t p;
    size_t written = 1;
    /* volatile: the compiler may not fold the divisions away */
    volatile int64_t min = INT64_MIN, minus_one = -1, zero = 0, seven = 7;

    /* no buffer: an unknown command's payload, and a broadcast of each profile */
    CHECK_EQ(osdk_payload_decode(NULL, 0, 0x7f, 0x7f, false, 0, &payload, &err), OSDK_OK);
    for (p = OSDK_PAYLOAD_PROFILE_M100_FW2_3; p <= OSDK_PAYLOAD_PROFILE_A3_FW3_1; p++)
        CHECK(osdk_payload_decode(NULL, 0, 0x02, 0x00, false, p, &payload, &err) != OSDK_OK);
    CHECK_EQ(osdk_payload_decode(NULL, 0, 0x02, 0x00, false, 0xff, &payload, &err), OSDK_OK);  /* unknown profile: raw */
    CHECK(osdk_frame_decode(NULL, 0, 0, &frame, &err) != OSDK_OK);   /* which class: the vectors say */
    CHECK(osdk_control_mode_decode(NULL, 0, &mode, &err) != OSDK_OK);
    CHECK(osdk_movement_control_decode(NULL, 0, &move, &err) != OSDK_OK);
    CHECK(osdk_broadcast_a3_fw3_1_decode(NULL, 0, &a3, &err) != OSDK_OK);
    CHECK(osdk_broadcast_m100_fw2_3_decode(NULL, 0, &m23, &err) != OSDK_OK);
    CHECK(osdk_broadcast_m100_fw3_1_decode(NULL, 0, &m31, &err) != OSDK_OK);
    CHECK_EQ(osdk_frame_problem(NULL, 0, NULL, 0), OSDK_ERR_TRUNCATED_FRAME);

    /* the CRCs of nothing are their initial values, as the spec's parameters say */
    CHECK_EQ(osdk_crc16(NULL, 0), osdk_crc16((const uint8_t *)"", 0));
    CHECK_EQ(osdk_crc32(NULL, 0), osdk_crc32((const uint8_t *)"", 0));

    /* a deframer fed nothing gives no event */
    CHECK(osdk_deframer_init(&d, window, sizeof window));
    osdk_deframer_feed(&d, NULL, 0, count_event, NULL);
    osdk_deframer_finish(&d, count_event, NULL);
    CHECK_EQ(events, 0);

    /* an empty ACK value, and no room at all: told, not written (LEN is 12 when DATA is empty) */
    CHECK_EQ(osdk_encode_frame(0, 0, true, 1, 1, NULL, 0, NULL, 0, &written), OSDK_ENCODE_BUFFER_TOO_SMALL);
    CHECK_EQ(written, 12);

    /* floor division and modulo at the ends of int64_t */
    CHECK_EQ(osdk_kdiv(min, minus_one), (uint64_t)INT64_MIN);   /* 2^63 wraps, as documented */
    CHECK_EQ(osdk_kmod(min, minus_one), 0);
    CHECK_EQ(osdk_kdiv(seven, minus_one), (uint64_t)(int64_t)-7);
    CHECK_EQ(osdk_kmod(seven, minus_one), 0);
    CHECK_EQ(osdk_kdiv(min, zero), 0);
    CHECK_EQ(osdk_kmod(min, zero), 0);
    CHECK_EQ(osdk_kdiv(-seven, 2), (uint64_t)(int64_t)-4);        /* floor, not truncation */
    CHECK_EQ(osdk_kmod(-seven, 2), 1);
    CHECK_EQ(osdk_kdiv(min, 2), (uint64_t)(INT64_MIN / 2));
    return check_done("test_edges");
}
