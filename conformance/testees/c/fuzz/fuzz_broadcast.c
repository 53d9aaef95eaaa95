/* libFuzzer target: the generated broadcast decoder, for every profile.
 *
 * The input is a broadcast value (flag word and items) as it sits in a
 * frame's DATA after set and id. Whatever the flag word promises, the
 * decoder may read only the bytes it was given (the DJI SDK copies the
 * promised items with unchecked memcpy); ASan's redzones around the
 * exactly-sized copy below catch any read past them. A decoded value is
 * also written as JSON into a fixed buffer. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "osdk_decoder.h"
#include "osdk_model_json.h"
#include "osdk_tables.h"

static osdk_payload_t g_payload;
static char g_json[1 << 16];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* an allocation of exactly `size` bytes, so any over-read is a finding */
    uint8_t *copy = (uint8_t *)malloc(size ? size : 1);
    if (copy == NULL) {
        return 0;
    }
    if (size) {
        memcpy(copy, data, size);
    }
    for (size_t p = 0; p < OSDK_PROFILE_COUNT; p++) {
        osdk_error_t err;
        osdk_status_t st = osdk_payload_decode(copy, size, 0x02, 0x00, false, osdk_profile_enum_values[p],
                                               &g_payload, &err);
        if (st == OSDK_OK) {
            osdk_json_t w;
            osdk_json_init(&w, g_json, sizeof g_json);
            osdk_payload_to_json(&g_payload, &w);
        } else if (st >= OSDK_STATUS_COUNT_) {
            abort();
        }
    }
    free(copy);
    return 0;
}
