/* The two worked frames of PROTOCOL-FACTS section 1 (osdk_conformance/reference/worked_examples.py). */
#include <string.h>

#include "check.h"
#include "osdk_decoder.h"
#include "osdk_deframer.h"
#include "osdk_model_json.h"

static osdk_frame_t frame;

static void movement(void)
{
    unsigned char raw[64];
    size_t n = unhex("aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba", raw);
    osdk_error_t err;
    const osdk_movement_control_t *mc;
    char json[8192];
    osdk_json_t w;
    CHECK_EQ(osdk_frame_problem(raw, n, NULL, 0), OSDK_OK);
    CHECK_EQ(osdk_frame_decode(raw, n, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &frame, &err), OSDK_OK);
    CHECK_EQ(frame.len, 35);
    CHECK_EQ(frame.session, 0);
    CHECK(!frame.is_ack);
    CHECK_EQ(frame.seq, 0x1234);
    CHECK_EQ(frame.crc16, 0x72e1);
    CHECK(frame.crc32_present);
    CHECK_EQ(frame.crc32, 0xba01dbfcu);
    CHECK(frame.data_present);
    CHECK_EQ(frame.data.tag, OSDK_FRAME_DATA_FRAME_DATA);
    CHECK_EQ(frame.data.u.frame_data.cmd_set, OSDK_FRAME_COMMAND_SET_CONTROL);
    CHECK_EQ(frame.data.u.frame_data.cmd_id, 3);
    CHECK_EQ(frame.data.u.frame_data.value.body.tag, OSDK_PAYLOAD_BODY_OSDK_MOVEMENT_CONTROL);
    mc = &frame.data.u.frame_data.value.body.u.osdk_movement_control;
    CHECK_EQ(mc->control_mode.horizontal_logic, OSDK_CONTROL_MODE_HORIZONTAL_LOGIC_HORI_VEL);
    CHECK_EQ(mc->control_mode.vertical_logic, OSDK_CONTROL_MODE_VERTICAL_LOGIC_VERT_VEL);
    CHECK_EQ(mc->control_mode.yaw_logic, OSDK_CONTROL_MODE_YAW_LOGIC_YAW_RATE);
    CHECK_EQ(mc->control_mode.horizontal_frame, OSDK_CONTROL_MODE_HORIZONTAL_FRAME_BODY);
    CHECK_EQ(mc->control_mode.stable_mode, OSDK_CONTROL_MODE_STABLE_MODE_STABLE);
    CHECK_EQ(mc->x.bits, 0x3f800000u);
    CHECK_EQ(mc->y.bits, 0xc0000000u);
    CHECK_EQ(mc->z.bits, 0x3f000000u);
    CHECK_EQ(mc->yaw.bits, 0x41f00000u);
    CHECK(mc->x.value == 1.0f && mc->y.value == -2.0f && mc->z.value == 0.5f && mc->yaw.value == 30.0f);
    osdk_json_init(&w, json, sizeof json);
    osdk_movement_control_to_json(mc, &w);
    CHECK(!w.overflow);
    CHECK(strcmp(json, "{\"control_mode\":{\"stable_mode\":{\"value\":1,\"name\":\"stable\"},"
                       "\"horizontal_frame\":{\"value\":1,\"name\":\"body\"},"
                       "\"yaw_logic\":{\"value\":1,\"name\":\"yaw_rate\"},"
                       "\"vertical_logic\":{\"value\":0,\"name\":\"vert_vel\"},"
                       "\"horizontal_logic\":{\"value\":1,\"name\":\"hori_vel\"}},"
                       "\"x\":{\"f32\":\"0x3f800000\",\"value\":1.0},\"y\":{\"f32\":\"0xc0000000\",\"value\":-2.0},"
                       "\"z\":{\"f32\":\"0x3f000000\",\"value\":0.5},\"yaw\":{\"f32\":\"0x41f00000\",\"value\":30.0}}") == 0);
}

static void broadcast(void)
{
    unsigned char raw[64];
    size_t n = unhex("aa1600000000000007001ede02000018035769c676b2", raw);
    osdk_error_t err;
    const osdk_broadcast_a3_fw3_1_t *b;
    CHECK_EQ(osdk_frame_problem(raw, n, NULL, 0), OSDK_OK);
    CHECK_EQ(osdk_frame_decode(raw, n, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &frame, &err), OSDK_OK);
    CHECK_EQ(frame.len, 22);
    CHECK_EQ(frame.seq, 7);
    CHECK_EQ(frame.data.u.frame_data.cmd_set, OSDK_FRAME_COMMAND_SET_PUSH);
    CHECK_EQ(frame.data.u.frame_data.cmd_id, 0);
    CHECK_EQ(frame.data.u.frame_data.value.body.tag, OSDK_PAYLOAD_BODY_BROADCAST);
    CHECK_EQ(frame.data.u.frame_data.value.body.u.broadcast.data.tag, OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1);
    b = &frame.data.u.frame_data.value.body.u.broadcast.data.u.osdk_broadcast_a3_fw3_1;
    CHECK(b->has_flight_status);
    CHECK(b->has_battery);
    CHECK(!b->has_time_stamp);
    CHECK(!b->time_stamp_present);
    CHECK(b->flight_status_present);
    CHECK_EQ(b->flight_status, 3);
    CHECK_EQ(b->battery, 87);
    /* one bit off in the CRC-32 */
    raw[n - 1] ^= 1;
    CHECK_EQ(osdk_frame_problem(raw, n, NULL, 0), OSDK_ERR_BAD_CRC32);
}

int main(void)
{
    movement();
    broadcast();
    return check_done("test_worked");
}
