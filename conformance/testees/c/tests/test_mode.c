/* Every value of the control mode byte: the generated bit-field decoder
 * and the generated classification tables agree with each other. */
#include <string.h>

#include "check.h"
#include "osdk_decoder.h"
#include "osdk_model_json.h"
#include "osdk_tables.h"

int main(void)
{
    unsigned byte;
    int p;
    char json[1024];
    for (byte = 0; byte < 256; byte++) {
        uint8_t b = (uint8_t)byte;
        osdk_control_mode_t m;
        osdk_error_t err;
        unsigned again;
        osdk_json_t w;
        CHECK_EQ(osdk_control_mode_decode(&b, 1, &m, &err), OSDK_OK);
        again = (unsigned)m.stable_mode | (unsigned)m.horizontal_frame << 1 | (unsigned)m.yaw_logic << 3 |
                (unsigned)m.vertical_logic << 4 | (unsigned)m.horizontal_logic << 6;
        CHECK_EQ(again, byte);
        osdk_json_init(&w, json, sizeof json);
        osdk_control_mode_to_json(&m, &w);
        CHECK(!w.overflow);
        /* a pattern the spec does not name is {"value": n, "name": null} */
        CHECK((strstr(json, "\"name\":null") != NULL) ==
              (m.horizontal_logic == 3 || m.vertical_logic == 3 || m.horizontal_frame >= 2));
        for (p = 0; p < OSDK_PROFILE_COUNT; p++) {
            int cls = osdk_mode_class[p][byte];
            int comb = osdk_mode_combination[p][byte];
            CHECK(cls >= 0 && cls < OSDK_MODE_CLASS_COUNT_);
            if (cls == OSDK_MODE_DOCUMENTED) {
                CHECK(comb >= 1 && comb <= OSDK_MAX_COMBINATION);
                /* a documented combination has a yaw range */
                CHECK(osdk_ranges[p][comb][OSDK_AXIS_YAW].has_min && osdk_ranges[p][comb][OSDK_AXIS_YAW].has_max);
            }
            /* undefined bit patterns are never documented */
            if (m.horizontal_logic == 3 || m.vertical_logic == 3 || m.horizontal_frame >= 2)
                CHECK(cls != OSDK_MODE_DOCUMENTED);
        }
    }
    /* the worked frame's mode byte */
    CHECK_EQ(osdk_mode_class[osdk_profile_index("a3-fw3.1")][0x4b], OSDK_MODE_DOCUMENTED);
    CHECK_EQ(osdk_mode_combination[osdk_profile_index("a3-fw3.1")][0x4b], 4);
    CHECK_EQ(osdk_profile_index("nope"), -1);
    CHECK(strcmp(osdk_command_name(1, 3), "movement_control") == 0);
    CHECK(strcmp(osdk_command_name(9, 9), "unknown") == 0);
    return check_done("test_mode");
}
