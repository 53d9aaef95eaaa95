/* Payload errors: a broadcast flag word that promises more than the payload
 * holds (truncated_payload, unlike the DJI SDK), reserved flag bits,
 * trailing bytes, and every profile's layout of the same flags. */
#include <string.h>

#include "check.h"
#include "osdk_decoder.h"

static osdk_payload_t p;

int main(void)
{
    unsigned char buf[256];
    osdk_error_t err;
    size_t n;

    /* flags 0x0001 (time stamp) but no bytes after the flag word */
    n = unhex("0100", buf);
    CHECK_EQ(osdk_payload_decode(buf, n, 2, 0, false, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &p, &err),
             OSDK_ERR_TRUNCATED_PAYLOAD);
    CHECK(strcmp(err.type, "osdk_broadcast_items::time_stamp") == 0);
    CHECK(strcmp(err.field, "time") == 0);
    CHECK_EQ(err.offset, 2);

    /* all twelve m100 items promised, four bytes given */
    n = unhex("ff0f01020304", buf);
    CHECK_EQ(osdk_payload_decode(buf, n, 2, 0, false, OSDK_PAYLOAD_PROFILE_M100_FW2_3, &p, &err),
             OSDK_ERR_TRUNCATED_PAYLOAD);
    /* the same four bytes are a whole fw2.3 time stamp item */
    n = unhex("010001020304", buf);
    CHECK_EQ(osdk_payload_decode(buf, n, 2, 0, false, OSDK_PAYLOAD_PROFILE_M100_FW2_3, &p, &err), OSDK_OK);
    CHECK_EQ(p.body.u.broadcast.data.u.osdk_broadcast_m100_fw2_3.time_stamp.time, 0x04030201u);
    /* ... but fw3.1's time stamp is 9 bytes */
    CHECK_EQ(osdk_payload_decode(buf, n, 2, 0, false, OSDK_PAYLOAD_PROFILE_M100_FW3_1, &p, &err),
             OSDK_ERR_TRUNCATED_PAYLOAD);

    /* reserved flag bits */
    n = unhex("0010", buf);
    CHECK_EQ(osdk_payload_decode(buf, n, 2, 0, false, OSDK_PAYLOAD_PROFILE_M100_FW3_1, &p, &err),
             OSDK_ERR_RESERVED_BITS);
    CHECK(strcmp(err.field, "reserved_flags") == 0);
    CHECK_EQ(osdk_payload_decode(buf, n, 2, 0, false, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &p, &err),
             OSDK_ERR_TRUNCATED_PAYLOAD); /* bit 12 is the battery on a3-fw3.1 */

    /* trailing bytes */
    n = unhex("00000102", buf);
    CHECK_EQ(osdk_payload_decode(buf, n, 2, 0, false, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &p, &err),
             OSDK_ERR_LENGTH_MISMATCH);
    CHECK(strcmp(err.field, "trailing") == 0);

    /* an unknown command keeps its bytes, an ACK is typed by its command */
    n = unhex("c0ffee", buf);
    CHECK_EQ(osdk_payload_decode(buf, n, 9, 9, false, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &p, &err), OSDK_OK);
    CHECK_EQ(p.body.tag, OSDK_PAYLOAD_BODY_UNKNOWN_VALUE);
    CHECK_EQ(p.body.u.unknown_value.raw.len, 3);
    CHECK(p.body.u.unknown_value.raw.ptr == buf);
    n = unhex("0200", buf);
    CHECK_EQ(osdk_payload_decode(buf, n, 1, 0, true, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &p, &err), OSDK_OK);
    CHECK_EQ(p.body.tag, OSDK_PAYLOAD_BODY_CONTROL_ACK_VALUE);
    CHECK_EQ(p.body.u.control_ack_value.ack_code, OSDK_PAYLOAD_CONTROL_ACK_OBTAINED);
    CHECK(strcmp(osdk_payload_control_ack_name(p.body.u.control_ack_value.ack_code), "obtained") == 0);
    CHECK(osdk_payload_control_ack_name(0x77) == NULL);

    /* a movement control value one byte short */
    n = unhex("4b0000803f000000c00000003f0000f0", buf);
    CHECK_EQ(osdk_payload_decode(buf, n, 1, 3, false, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &p, &err),
             OSDK_ERR_TRUNCATED_PAYLOAD);
    CHECK(strcmp(err.field, "yaw") == 0);

    /* no buffer at all */
    CHECK_EQ(osdk_payload_decode(NULL, 0, 0, 0, false, 0, &p, &err), OSDK_ERR_TRUNCATED_PAYLOAD);
    return check_done("test_payload");
}
