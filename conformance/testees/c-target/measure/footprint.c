/*
 * footprint.c - the smallest programs that use the library the way a
 * board does, one per feature, for `osdkc bench --only footprint`
 * (docs/PERFORMANCE.md). FEATURE selects how much of it is linked:
 *
 *   0  the board alone: start-up, the UART, a loop that takes bytes
 *   1  receive: every byte into the deframer, frames and rejections counted
 *   2  + decode: each frame decoded for its profile, two broadcast items read
 *   3  + encode: each broadcast answered with a movement control frame
 *
 * What 1 to 3 cost beyond 0 is the library's. State is static, as on a
 * board, so the linker's figures hold all of it but the stack.
 */
#include <stdint.h>

#include "board.h"
#if FEATURE >= 1
#include "osdk_deframer.h"
#endif
#if FEATURE >= 2
#include "osdk_broadcast.h"
#endif
#if FEATURE >= 3
#include "osdk_encode.h"
#endif

#ifndef FEATURE
#error "build with -DFEATURE=0..3"
#endif

volatile uint32_t g_seen; /* what the loop did, kept so nothing is optimised away */

#if FEATURE >= 1
static uint8_t g_window[OSDK_DEFRAMER_MIN_BUFFER];
static osdk_deframer_t g_rx;

#if FEATURE >= 3
static uint16_t g_seq;

static void answer(void)
{
    uint8_t value[OSDK_MOVEMENT_CONTROL_SIZE];
    uint8_t frame[OSDK_FRAME_HEADER_LEN + 2u + OSDK_MOVEMENT_CONTROL_SIZE + 4u];
    size_t n = 0;
    osdk_encode_movement_control(0x4Au, 0.0f, 0.0f, 0.0f, 0.0f, value);
    if (osdk_encode_frame(OSDK_MOVEMENT_CONTROL_CMD_SET, OSDK_MOVEMENT_CONTROL_CMD_ID, false, 0u, g_seq++, value,
                          sizeof value, frame, sizeof frame, &n) == OSDK_ENCODE_OK)
        board_write((const char *)frame, n);
}
#endif

static void on_event(void *user, const osdk_event_t *ev)
{
    (void)user;
    if (ev->kind != OSDK_EVENT_FRAME) {
        g_seen += 0x10000u;
        return;
    }
#if FEATURE >= 2
    {
        osdk_frame_t f;
        osdk_error_t err;
        const osdk_payload_broadcast_t *b;
        if (osdk_frame_decode(ev->raw, ev->length, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &f, &err) != OSDK_OK) return;
        b = osdk_broadcast_of(&f);
        if (b != NULL) {
            const uint8_t *battery = osdk_broadcast_battery(b);
            const osdk_broadcast_items_quaternion_t *q = osdk_broadcast_quaternion(b);
            g_seen += (battery ? *battery : 0u) + (q ? q->q0.bits : 0u);
#if FEATURE >= 3
            answer();
#endif
        }
    }
#else
    g_seen++;
#endif
}
#endif

int main(void)
{
#if FEATURE >= 1
    osdk_deframer_init(&g_rx, g_window, sizeof g_window);
#endif
    for (;;) {
        uint8_t byte = (uint8_t)board_getc();
#if FEATURE >= 1
        osdk_deframer_feed(&g_rx, &byte, 1u, on_event, NULL);
#else
        g_seen += byte;
#endif
    }
}
