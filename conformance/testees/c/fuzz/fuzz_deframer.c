/* libFuzzer target: the generated streaming deframer and frame decoder.
 *
 * The input is a byte stream. Its first byte picks the profile and the
 * size of the reads the stream arrives in, so chunk boundaries land
 * everywhere; every frame the deframer hands over is decoded and written
 * as JSON into a fixed buffer, which is what a receiver on a board does.
 * Besides the sanitizers' findings, it checks the deframer's promises:
 * events come in stream order, inside the input, and each frame event is
 * exactly LEN bytes starting with the start byte. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "osdk_decoder.h"
#include "osdk_deframer.h"
#include "osdk_model_json.h"
#include "osdk_tables.h"

typedef struct {
    uint8_t profile;
    uint64_t total;
    uint64_t next_offset;
} state_t;

static osdk_frame_t g_frame;
static char g_json[1 << 16];

static void on_event(void *user, const osdk_event_t *ev)
{
    state_t *st = (state_t *)user;
    if (ev->offset < st->next_offset || ev->offset + ev->length > st->total) {
        abort(); /* out of order, or outside the input */
    }
    st->next_offset = ev->offset + (ev->kind == OSDK_EVENT_GARBAGE ? ev->length : 1);
    if (ev->kind != OSDK_EVENT_FRAME) {
        return;
    }
    if (ev->length < 12 || ev->raw[0] != 0xAA || (size_t)((ev->raw[1] | ev->raw[2] << 8) & 0x3FF) != ev->length) {
        abort(); /* a frame event that is not one whole frame */
    }
    osdk_error_t err;
    if (osdk_frame_decode(ev->raw, ev->length, st->profile, &g_frame, &err) == OSDK_OK) {
        osdk_json_t w;
        osdk_json_init(&w, g_json, sizeof g_json);
        osdk_frame_to_json(&g_frame, &w);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t window[OSDK_DEFRAMER_MIN_BUFFER];
    if (size < 1) {
        return 0;
    }
    state_t st = {osdk_profile_enum_values[data[0] % OSDK_PROFILE_COUNT], size - 1, 0};
    size_t chunk = (size_t)(data[0] >> 2) + 1; /* 1..64 bytes per read */
    osdk_deframer_t d;
    if (!osdk_deframer_init(&d, window, sizeof window)) {
        abort();
    }
    for (size_t pos = 1; pos < size; pos += chunk) {
        size_t n = size - pos < chunk ? size - pos : chunk;
        osdk_deframer_feed(&d, data + pos, n, on_event, &st);
    }
    osdk_deframer_finish(&d, on_event, &st);
    return 0;
}
