/*
 * encode_only.c - the smallest testee on the kit: an implementation that
 * only builds movement control values (the command an onboard computer
 * sends at 50 Hz), put under the conformance runner with one callback.
 *
 *   make -C conformance/testee-kit/c example
 *   osdkc run --testee conformance/testee-kit/c/build/encode-only
 *
 * `my_encode_movement` stands for the implementation being wrapped: its
 * code is its own, the kit only carries requests to it and answers back.
 */
#include <stdint.h>
#include <stdlib.h>

#include "okit.h"

/* ---- the implementation under test ---------------------------------------------------------------- */

/* Control mode byte, then x, y, z, yaw as little-endian IEEE-754 single floats: 17 bytes. */
static void my_encode_movement(uint8_t mode, const uint32_t setpoint_bits[4], uint8_t out[17])
{
    int i, k;
    out[0] = mode;
    for (i = 0; i < 4; i++)
        for (k = 0; k < 4; k++) out[1 + 4 * i + k] = (uint8_t)(setpoint_bits[i] >> (8 * k));
}

/* ---- the callback ----------------------------------------------------------------------------------- */

static void encode_movement_control(okit_request *req)
{
    static const char *const axes[4] = {"x", "y", "z", "yaw"};
    uint32_t bits[4];
    uint8_t value[17];
    int64_t mode;
    int i;
    osdk_json_t *w;
    if (!okit_int(req, "mode", 0, 255, &mode)) return;   /* the kit has answered bad_request */
    for (i = 0; i < 4; i++)
        if (!okit_f32(req, axes[i], &bits[i])) return;
    my_encode_movement((uint8_t)mode, bits, value);
    if (!(w = okit_result(req, 128))) return;
    osdk_json_begin_object(w);
    osdk_json_key(w, "hex");
    osdk_json_hex(w, value, sizeof value);
    osdk_json_end_object(w);
}

int main(int argc, char **argv)
{
    static const char *const profiles[] = {NULL}; /* it decodes nothing: no profile */
    okit_testee t = {0};
    t.name = "encode-only example";
    t.profiles = profiles;
    t.encode_movement_control = encode_movement_control;
    return okit_main(&t, argc, argv);
}
