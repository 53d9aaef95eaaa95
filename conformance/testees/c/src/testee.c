/*
 * testee.c - the bundled C testee: the generated decoder of generated/c/
 * behind the testee protocol of conformance/PROTOCOL.md (JSON Lines on
 * stdin/stdout).
 *
 * Layouts, enums, `valid` checks, error classes, the receiver (deframer),
 * both CRCs, the JSON value model and the rule tables all come from the
 * generated code. This file only reads requests, checks their arguments,
 * matches ACKs to commands in a stream (the pending table) and applies
 * the control-mode rules the tables hold. Request lines use the heap; the
 * decoder does not.
 *
 * With arguments (`--bench FILE --profile P`) it runs the bench mode
 * instead: decode_stream's work on a file, counted, not printed.
 *
 * The same file is the on-target testee (conformance/testees/c-target):
 * built with OKIT_PORT the kit reads the board's UART and uses no heap,
 * and the bench mode, which reads files, is left out.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime for the bench mode */
#include <errno.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "okit.h"
#include "osdk_acks.h"
#include "osdk_decoder.h"
#include "osdk_deframer.h"
#include "osdk_encode.h"
#include "osdk_model_json.h"
#include "osdk_tables.h"

#ifndef TESTEE_NAME
#define TESTEE_NAME "osdk-c-generated"
#endif
/* One event's JSON: a frame of 1023 bytes and its value model take under 8 KiB. */
#ifndef EVENT_BUF
#define EVENT_BUF (64u << 10)
#endif


/* ---- answers ------------------------------------------------------------------------------ */

/* A decoder error as the answer: its class, and where the generated decoder stopped. */
static void decode_error(okit_request *req, const osdk_error_t *err, const char *what)
{
    char detail[256];
    snprintf(detail, sizeof detail, "%s: %s.%s failed at offset %lu", what, err->type ? err->type : "?",
             err->field ? err->field : "?", (unsigned long)err->offset);
    okit_error(req, osdk_status_name(err->status), detail);
}

/* ---- shared pieces ------------------------------------------------------------------------ */

static char g_event_buf[EVENT_BUF]; /* one event's JSON */
static osdk_frame_t g_frame; /* large structs live here, not on the stack */
static osdk_payload_t g_payload;

static void err_detail(char *out, size_t cap, const osdk_error_t *err)
{
    snprintf(out, cap, "%s.%s failed at offset %lu", err->type ? err->type : "?", err->field ? err->field : "?",
             (unsigned long)err->offset);
}

/* ---- decode_payload / decode_frame ---------------------------------------------------------------- */

static void op_decode_payload(okit_request *req)
{
    int profile = okit_profile(req);
    uint8_t *data = NULL;
    size_t len = 0;
    int64_t cmd_set, cmd_id;
    bool is_ack;
    osdk_error_t err;
    osdk_json_t *w;
    if (!okit_hex(req, "hex", &data, &len) || !okit_int(req, "cmd_set", 0, 255, &cmd_set) ||
        !okit_int(req, "cmd_id", 0, 255, &cmd_id) || !okit_bool(req, "is_ack", &is_ack)) {
        okit_free(data);
        return;
    }
    if (osdk_payload_decode(data, len, (uint8_t)cmd_set, (uint8_t)cmd_id, is_ack, osdk_profile_enum_values[profile],
                            &g_payload, &err) != OSDK_OK) {
        decode_error(req, &err, "payload");
        okit_free(data);
        return;
    }
    if (!(w = okit_result(req, (1u << 20) + 8 * len))) {
        okit_free(data);
        return;
    }
    osdk_json_begin_object(w);
    osdk_json_key(w, "value");
    osdk_payload_field_to_json(&g_payload, "body", w);
    osdk_json_end_object(w);
    okit_free(data);
}

static void op_decode_frame(okit_request *req)
{
    int profile = okit_profile(req);
    uint8_t *data = NULL;
    size_t len = 0;
    char detail[256];
    osdk_status_t st;
    osdk_error_t err;
    osdk_json_t *w;
    if (!okit_hex(req, "hex", &data, &len)) {
        return;
    }
    st = osdk_frame_problem(data, len, detail, sizeof detail);
    if (st != OSDK_OK) {
        okit_error(req, osdk_status_name(st), detail);
        okit_free(data);
        return;
    }
    if (osdk_frame_decode(data, len, osdk_profile_enum_values[profile], &g_frame, &err) != OSDK_OK) {
        decode_error(req, &err, "frame");
        okit_free(data);
        return;
    }
    if (!(w = okit_result(req, (1u << 20) + 8 * len))) {
        okit_free(data);
        return;
    }
    osdk_json_begin_object(w);
    osdk_json_key(w, "frame");
    osdk_frame_to_json(&g_frame, w);
    osdk_json_end_object(w);
    okit_free(data);
}

/* ---- control mode ------------------------------------------------------------------------------------- */

static void op_classify(okit_request *req)
{
    int profile = okit_profile(req);
    int64_t byte;
    uint8_t one;
    osdk_control_mode_t mode;
    osdk_error_t err;
    osdk_json_t *w;
    int comb;
    if (!okit_int(req, "byte", 0, 255, &byte)) {
        return;
    }
    one = (uint8_t)byte;
    if (osdk_control_mode_decode(&one, 1, &mode, &err) != OSDK_OK) {
        decode_error(req, &err, "control mode");
        return;
    }
    if (!(w = okit_result(req, 1u << 16))) {
        return;
    }
    osdk_json_begin_object(w);
    osdk_json_key(w, "fields");
    osdk_control_mode_to_json(&mode, w);
    osdk_json_key(w, "classification");
    osdk_json_string(w, osdk_mode_class_names[osdk_mode_class[profile][one]]);
    osdk_json_key(w, "combination");
    comb = osdk_mode_combination[profile][one];
    if (comb < 0) osdk_json_null(w);
    else osdk_json_int(w, comb);
    osdk_json_end_object(w);
}

/* Which range each setpoint is checked against (PROTOCOL.md check_movement_control). */
static const struct {
    const char *name;
    osdk_axis_t axis;
} SETPOINTS[4] = {{"x", OSDK_AXIS_HORIZONTAL}, {"y", OSDK_AXIS_HORIZONTAL}, {"z", OSDK_AXIS_VERTICAL},
                  {"yaw", OSDK_AXIS_YAW}};

static void op_check_movement(okit_request *req)
{
    int profile = okit_profile(req);
    uint8_t *data = NULL;
    size_t len = 0;
    osdk_error_t err;
    osdk_json_t *w;
    const osdk_movement_control_t *mc;
    const osdk_f32_t *values[4];
    uint8_t byte;
    int comb, i;
    char detail[256];
    if (!okit_hex(req, "hex", &data, &len)) {
        return;
    }
    /* as a command value: the movement control command's payload, trailing-bytes check included */
    if (osdk_payload_decode(data, len, 0x01, 0x03, false, osdk_profile_enum_values[profile], &g_payload, &err) !=
        OSDK_OK) {
        decode_error(req, &err, "movement control");
        okit_free(data);
        return;
    }
    if (g_payload.body.tag != OSDK_PAYLOAD_BODY_OSDK_MOVEMENT_CONTROL) {
        okit_error(req, "undecodable", "the payload is not a movement control value");
        okit_free(data);
        return;
    }
    mc = &g_payload.body.u.osdk_movement_control;
    byte = data[0];
    okit_free(data);
    if (osdk_mode_class[profile][byte] != OSDK_MODE_DOCUMENTED) {
        snprintf(detail, sizeof detail, "mode byte 0x%02x is %s on %s", (unsigned)byte,
                 osdk_mode_class_names[osdk_mode_class[profile][byte]], osdk_profile_ids[profile]);
        okit_error(req, "undefined_mode", detail);
        return;
    }
    comb = osdk_mode_combination[profile][byte];
    values[0] = &mc->x;
    values[1] = &mc->y;
    values[2] = &mc->z;
    values[3] = &mc->yaw;
    for (i = 0; i < 4; i++) {
        const osdk_range_t *lim = &osdk_ranges[profile][comb][SETPOINTS[i].axis];
        uint32_t bits = values[i]->bits;
        double v = (double)values[i]->value;
        bool nonfinite = ((bits >> 23) & 0xffu) == 0xffu;
        if (nonfinite || (lim->has_min && v < lim->min) || (lim->has_max && v > lim->max)) {
            snprintf(detail, sizeof detail, "%s (f32 0x%08lx) is outside the %s range", SETPOINTS[i].name,
                     (unsigned long)bits, osdk_axis_names[SETPOINTS[i].axis]);
            okit_error(req, "out_of_range", detail);
            return;
        }
    }
    if (!(w = okit_result(req, 1u << 16))) {
        return;
    }
    osdk_json_begin_object(w);
    osdk_json_key(w, "value");
    osdk_movement_control_to_json(mc, w);
    osdk_json_key(w, "combination");
    osdk_json_int(w, comb);
    osdk_json_end_object(w);
}

/* ---- decode_stream ------------------------------------------------------------------------------------ */

typedef struct {
    int profile;
    bool first_event;
    osdk_json_t *out;   /* the answer's "events" array */
    osdk_acks_t acks; /* one slot per session 2..31 (ACK matching) */
} stream_ctx_t;

static void write_event(stream_ctx_t *s, osdk_json_t *w)
{
    if (w->overflow) {
        static const char fallback[] =
            "{\"kind\": \"error\", \"error\": \"undecodable\", \"detail\": \"event too large\"}";
        osdk_json_raw(s->out, s->first_event ? "" : ", ");
        osdk_json_raw(s->out, fallback);
    } else {
        osdk_json_raw(s->out, s->first_event ? "" : ", ");
        osdk_json_raw_n(s->out, w->buf, w->len);
    }
    s->first_event = false;
}

static void event_head(osdk_json_t *w, uint64_t offset, const char *kind)
{
    osdk_json_init(w, g_event_buf, EVENT_BUF);
    osdk_json_begin_object(w);
    osdk_json_key(w, "offset");
    osdk_json_uint(w, offset);
    osdk_json_key(w, "kind");
    osdk_json_string(w, kind);
}

static void frame_error(stream_ctx_t *s, const osdk_event_t *ev, const osdk_error_t *err, const char *ack_of)
{
    osdk_json_t w;
    char detail[256];
    err_detail(detail, sizeof detail, err);
    event_head(&w, ev->offset, "error");
    osdk_json_key(&w, "error");
    osdk_json_string(&w, osdk_status_name(err->status));
    osdk_json_key(&w, "detail");
    osdk_json_string(&w, detail);
    osdk_json_key(&w, "length");
    osdk_json_uint(&w, ev->length);
    if (ack_of) {
        osdk_json_key(&w, "ack_of");
        osdk_json_string(&w, ack_of);
    }
    osdk_json_end_object(&w);
    write_event(s, &w);
}

/* What decode_stream and the bench mode both make of a deframed frame. */
typedef struct {
    bool ok;             /* false: err says why the frame or its ACK value was rejected */
    osdk_error_t err;
    const char *command; /* a command frame's name */
    const char *ack_of;  /* an ACK matched to a command earlier in the stream */
    bool have_ack;       /* g_payload holds that ACK's value */
} frame_result_t;

/* Decode into g_frame (and g_payload for a matched ACK), keeping the ACK slots. */
static void decode_stream_frame(stream_ctx_t *s, const osdk_event_t *ev, frame_result_t *r)
{
    bool plain, header_only;
    memset(r, 0, sizeof *r);
    if (osdk_frame_decode(ev->raw, ev->length, osdk_profile_enum_values[s->profile], &g_frame, &r->err) != OSDK_OK)
        return;
    header_only = g_frame.len == OSDK_FRAME_HEADER_LEN;
    plain = g_frame.data_present && g_frame.data.tag == OSDK_FRAME_DATA_FRAME_DATA;
    if (g_frame.is_ack && (plain || header_only)) { /* a header-only ACK is matched too, its value empty */
        uint8_t cmd_set, cmd_id;
        if (osdk_acks_take(&s->acks, g_frame.session, g_frame.seq, &cmd_set, &cmd_id)) {
            static const uint8_t none[1] = {0};
            const uint8_t *value = plain ? g_frame.data.u.frame_data.ack_value.ptr : none;
            size_t value_len = plain ? g_frame.data.u.frame_data.ack_value.len : 0;
            r->ack_of = osdk_command_name(cmd_set, cmd_id);
            if (osdk_payload_decode(value, value_len, cmd_set, cmd_id, true,
                                    osdk_profile_enum_values[s->profile], &g_payload, &r->err) != OSDK_OK)
                return;
            r->have_ack = true;
        }
    } else if (plain && !g_frame.is_ack) {
        const osdk_frame_frame_data_t *fd = &g_frame.data.u.frame_data;
        r->command = osdk_command_name(fd->cmd_set, fd->cmd_id);
        osdk_acks_command(&s->acks, g_frame.session, g_frame.seq, fd->cmd_set, fd->cmd_id);
    }
    r->ok = true;
}

static void on_frame(stream_ctx_t *s, const osdk_event_t *ev)
{
    frame_result_t r;
    osdk_json_t w;
    decode_stream_frame(s, ev, &r);
    if (!r.ok) {
        frame_error(s, ev, &r.err, r.ack_of);
        return;
    }
    event_head(&w, ev->offset, "frame");
    if (r.command) {
        osdk_json_key(&w, "command");
        osdk_json_string(&w, r.command);
    }
    if (r.ack_of) {
        osdk_json_key(&w, "ack_of");
        osdk_json_string(&w, r.ack_of);
    }
    if (r.have_ack) {
        osdk_json_key(&w, "ack");
        osdk_payload_field_to_json(&g_payload, "body", &w);
    }
    osdk_json_key(&w, "frame");
    osdk_frame_to_json(&g_frame, &w);
    osdk_json_end_object(&w);
    write_event(s, &w);
}

static void on_event(void *user, const osdk_event_t *ev)
{
    stream_ctx_t *s = user;
    osdk_json_t w;
    switch (ev->kind) {
    case OSDK_EVENT_FRAME:
        on_frame(s, ev);
        return;
    case OSDK_EVENT_GARBAGE:
        event_head(&w, ev->offset, "garbage");
        osdk_json_key(&w, "length");
        osdk_json_uint(&w, ev->length);
        osdk_json_end_object(&w);
        write_event(s, &w);
        return;
    case OSDK_EVENT_ERROR:
    default:
        event_head(&w, ev->offset, "error");
        osdk_json_key(&w, "error");
        osdk_json_string(&w, osdk_status_name(ev->error));
        osdk_json_key(&w, "detail");
        osdk_json_string(&w, ev->detail ? ev->detail : "");
        osdk_json_key(&w, "length");
        osdk_json_uint(&w, ev->length);
        osdk_json_end_object(&w);
        write_event(s, &w);
        return;
    }
}

static stream_ctx_t g_stream;
static uint8_t g_window[OSDK_DEFRAMER_MIN_BUFFER];

static void op_decode_stream(okit_request *req)
{
    int profile = okit_profile(req);
    uint8_t *data = NULL;
    uint64_t *chunks = NULL;
    size_t len = 0, pos = 0, count = 0, i;
    osdk_deframer_t d;
    osdk_json_t *w;
    if (!okit_hex(req, "hex", &data, &len)) return;
    if (!okit_sizes(req, "chunks", &chunks, &count)) {
        okit_free(data);
        return;
    }
    /* room for the events: a few hundred bytes per input byte at worst (one rejection each) */
    if (!(w = okit_result(req, (1u << 20) + 512u * len))) {
        okit_free(data);
        okit_free(chunks);
        return;
    }
    memset(&g_stream, 0, sizeof g_stream);
    g_stream.profile = profile;
    g_stream.first_event = true;
    g_stream.out = w;
    osdk_acks_init(&g_stream.acks);
    osdk_deframer_init(&d, g_window, sizeof g_window);
    osdk_json_begin_object(w);
    osdk_json_key(w, "events");
    osdk_json_begin_array(w);
    /* reads of the given sizes; what they leave over arrives as one last read */
    for (i = 0; i < count && pos < len; i++) {
        size_t n = chunks[i] > (uint64_t)(len - pos) ? len - pos : (size_t)chunks[i];
        osdk_deframer_feed(&d, data + pos, n, on_event, &g_stream);
        pos += n;
    }
    if (pos < len) osdk_deframer_feed(&d, data + pos, len - pos, on_event, &g_stream);
    osdk_deframer_finish(&d, on_event, &g_stream);
    osdk_json_end_array(w);
    osdk_json_end_object(w);
    okit_free(data);
    okit_free(chunks);
}

/* ---- bench mode (conformance/PROTOCOL.md, "Bench mode") --------------------------------------------------- */
#ifndef OKIT_PORT

#define BENCH_READ (64u * 1024u)
#define BENCH_USAGE "usage: --bench FILE|- --profile P"

typedef struct {
    stream_ctx_t *stream;
    uint64_t frames, errors, garbage_bytes;
} bench_ctx_t;

/* decode_stream's work per event, counted instead of written as JSON */
static void bench_event(void *user, const osdk_event_t *ev)
{
    bench_ctx_t *b = user;
    frame_result_t r;
    switch (ev->kind) {
    case OSDK_EVENT_FRAME:
        decode_stream_frame(b->stream, ev, &r);
        if (r.ok) b->frames++;
        else b->errors++;
        return;
    case OSDK_EVENT_GARBAGE:
        b->garbage_bytes += ev->length;
        return;
    case OSDK_EVENT_ERROR:
    default:
        b->errors++;
        return;
    }
}

static double monotonic_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static int bench_fail(const char *fmt, const char *a, const char *b)
{
    fputs("osdk-c-testee --bench: ", stderr);
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    return 2;
}

static int bench_main(int argc, char **argv)
{
    static uint8_t chunk[BENCH_READ];
    const char *path = NULL, *profile_id = NULL;
    bench_ctx_t b;
    osdk_deframer_t d;
    FILE *in;
    uint64_t total = 0;
    size_t n;
    double start, seconds;
    int i, profile;
    for (i = 1; i < argc; i += 2) {
        const char **slot = strcmp(argv[i], "--bench") == 0     ? &path
                            : strcmp(argv[i], "--profile") == 0 ? &profile_id
                                                                : NULL;
        if (!slot) return bench_fail("unknown argument '%s'; %s", argv[i], BENCH_USAGE);
        if (i + 1 >= argc) return bench_fail("%s needs a value; %s", argv[i], BENCH_USAGE);
        if (*slot) return bench_fail("%s given twice; %s", argv[i], BENCH_USAGE);
        *slot = argv[i + 1];
    }
    if (!path || !profile_id) return bench_fail("%s%s", BENCH_USAGE, "");
    profile = osdk_profile_index(profile_id);
    if (profile < 0) {
        char known[128] = "";
        for (i = 0; i < OSDK_PROFILE_COUNT; i++) {
            if (i) strncat(known, ", ", sizeof known - strlen(known) - 1);
            strncat(known, osdk_profile_ids[i], sizeof known - strlen(known) - 1);
        }
        return bench_fail("unknown profile '%s' (known: %s)", profile_id, known);
    }
    in = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    if (!in) return bench_fail("cannot read %s: %s", path, strerror(errno));
    memset(&g_stream, 0, sizeof g_stream);
    g_stream.profile = profile;
    osdk_acks_init(&g_stream.acks);
    memset(&b, 0, sizeof b);
    b.stream = &g_stream;
    osdk_deframer_init(&d, g_window, sizeof g_window);
    start = monotonic_seconds();
    while ((n = fread(chunk, 1, sizeof chunk, in)) > 0) {
        total += n;
        osdk_deframer_feed(&d, chunk, n, bench_event, &b);
    }
    if (ferror(in)) {
        int e = errno;
        if (in != stdin) fclose(in);
        return bench_fail("cannot read %s: %s", path, strerror(e));
    }
    osdk_deframer_finish(&d, bench_event, &b);
    seconds = monotonic_seconds() - start;
    if (in != stdin) fclose(in);
    printf("{\"impl\": \"c\", \"profile\": \"%s\", \"bytes\": %llu, \"frames\": %llu, \"errors\": %llu, "
           "\"garbage_bytes\": %llu, \"seconds\": %.6f}\n",
           osdk_profile_ids[profile], (unsigned long long)total, (unsigned long long)b.frames,
           (unsigned long long)b.errors, (unsigned long long)b.garbage_bytes, seconds);
    return fflush(stdout) == 0 ? 0 : 2;
}
#endif

/* ---- encoders ------------------------------------------------------------------------------------------- */

static void hex_result(okit_request *req, const uint8_t *bytes, size_t n)
{
    osdk_json_t *w;
    if (!(w = okit_result(req, (1u << 12) + 2 * n))) return;
    osdk_json_begin_object(w);
    osdk_json_key(w, "hex");
    osdk_json_hex(w, bytes, n);
    osdk_json_end_object(w);
}

static void op_encode_movement(okit_request *req)
{
    static const char *const keys[4] = {"x", "y", "z", "yaw"};
    int64_t mode;
    uint32_t bits[4];
    uint8_t out[OSDK_MOVEMENT_CONTROL_SIZE];
    unsigned i;
    if (!okit_int(req, "mode", 0, 255, &mode)) return;
    for (i = 0; i < 4; i++) {
        if (!okit_f32(req, keys[i], &bits[i])) return;
    }
    /* the bits variant: a signalling NaN's payload goes out as it came */
    hex_result(req, out, osdk_encode_movement_control_bits((uint8_t)mode, bits[0], bits[1], bits[2], bits[3], out));
}

static void op_encode_frame(okit_request *req)
{
    bool is_ack;
    int64_t session, seq, cmd_set = 0, cmd_id = 0;
    uint8_t *value = NULL;
    size_t vlen = 0, written = 0;
    uint8_t frame[OSDK_ENCODE_FRAME_MAX_LEN];
    osdk_encode_status_t st;
    if (!okit_bool(req, "is_ack", &is_ack) || !okit_int(req, "session", 0, 31, &session) ||
        !okit_int(req, "seq", 0, 0xFFFF, &seq) || !okit_hex(req, "value", &value, &vlen)) {
        okit_free(value);
        return;
    }
    if (is_ack) {
        if (okit_has(req, "cmd_set") || okit_has(req, "cmd_id")) {
            okit_free(value);
            okit_error(req, "bad_request", "an ACK frame has no cmd_set or cmd_id");
            return;
        }
    } else if (!okit_int(req, "cmd_set", 0, 255, &cmd_set) || !okit_int(req, "cmd_id", 0, 255, &cmd_id)) {
        okit_free(value);
        return;
    }
    st = osdk_encode_frame((uint8_t)cmd_set, (uint8_t)cmd_id, is_ack, (uint8_t)session, (uint16_t)seq, value, vlen,
                           frame, sizeof frame, &written);
    okit_free(value);
    if (st == OSDK_ENCODE_OK) {
        hex_result(req, frame, written);
    } else if (st == OSDK_ENCODE_IMPOSSIBLE_LENGTH) {
        okit_error(req, osdk_encode_status_name(st), "the frame would be longer than its 10-bit LEN can say");
    } else if (st == OSDK_ENCODE_BAD_SESSION) {
        okit_error(req, osdk_encode_status_name(st), "an ACK frame cannot be in session 0");
    } else {
        okit_error(req, "internal_error", osdk_encode_status_name(st));
    }
}

/* ---- the testee ------------------------------------------------------------------------------------------ */

int main(int argc, char **argv)
{
    static const char *profiles[OSDK_PROFILE_COUNT + 1]; /* okit_profile() is then the generated profile index */
    okit_testee t;
    int i;
    for (i = 0; i < OSDK_PROFILE_COUNT; i++) profiles[i] = osdk_profile_ids[i];
    memset(&t, 0, sizeof t);
    t.name = TESTEE_NAME;
    t.profiles = profiles;
    t.decode_stream = op_decode_stream;
    t.decode_frame = op_decode_frame;
    t.decode_payload = op_decode_payload;
    t.classify_control_mode = op_classify;
    t.check_movement_control = op_check_movement;
    t.encode_movement_control = op_encode_movement;
    t.encode_frame = op_encode_frame;
#ifndef OKIT_PORT
    t.bench = bench_main;
#endif
    return okit_main(&t, argc, argv);
}

/* Sanitizer builds: a finding aborts the process (the runner reports a
 * testee_crash) instead of only printing. */
#if defined(__SANITIZE_ADDRESS__)
const char *__asan_default_options(void);
const char *__asan_default_options(void)
{
    return "abort_on_error=1:detect_leaks=1";
}
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
const char *__ubsan_default_options(void);
const char *__ubsan_default_options(void)
{
    return "halt_on_error=1:print_stacktrace=1";
}
#endif
