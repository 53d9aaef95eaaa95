/*
 * okit.c - see okit.h. The loop, the argument readers and the answers of
 * conformance/PROTOCOL.md, written once for every C or C++ testee.
 */
#include "okit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "jsonread.h"

struct okit_request {
    const okit_testee *testee;
    const jv_t *json;
    const char *op;
    int profile;
    bool answered;
    char *result_buf;   /* okit_result's buffer, written out when the callback returns */
    osdk_json_t result;
};

/* ---- writing answers ------------------------------------------------------------------------- */

static void emit_line(const char *text, size_t n)
{
    fwrite(text, 1, n, stdout);
    fputc('\n', stdout);
    fflush(stdout);
}

static void emit_error(const char *error_class, const char *detail)
{
    char buf[1024];
    osdk_json_t w;
    osdk_json_init(&w, buf, sizeof buf);
    osdk_json_begin_object(&w);
    osdk_json_key(&w, "ok");
    osdk_json_bool(&w, false);
    osdk_json_key(&w, "error");
    osdk_json_string(&w, error_class);
    osdk_json_key(&w, "detail");
    osdk_json_string(&w, detail);
    osdk_json_end_object(&w);
    if (w.overflow) {
        static const char fallback[] = "{\"ok\": false, \"error\": \"internal_error\", \"detail\": \"detail too long\"}";
        emit_line(fallback, sizeof fallback - 1);
        return;
    }
    emit_line(buf, w.len);
}

static bool first_answer(okit_request *req)
{
    if (req->answered) {
        fprintf(stderr, "okit: a second answer to one %s request was dropped\n", req->op);
        return false;
    }
    req->answered = true;
    return true;
}

void okit_error(okit_request *req, const char *error_class, const char *detail)
{
    if (first_answer(req)) emit_error(error_class, detail);
}

void okit_unsupported(okit_request *req)
{
    static const char text[] = "{\"ok\": false, \"unsupported\": true}";
    if (first_answer(req)) emit_line(text, sizeof text - 1);
}

osdk_json_t *okit_result(okit_request *req, size_t room)
{
    if (!first_answer(req)) return NULL;
    req->result_buf = malloc(room + 64);
    if (!req->result_buf) {
        emit_error("internal_error", "out of memory for the answer");
        return NULL;
    }
    osdk_json_init(&req->result, req->result_buf, room + 64);
    osdk_json_begin_object(&req->result);
    osdk_json_key(&req->result, "ok");
    osdk_json_bool(&req->result, true);
    osdk_json_key(&req->result, "result");
    return &req->result;
}

/* After the callback: the result it wrote, closed; or internal_error when it answered nothing. */
static void finish(okit_request *req)
{
    if (!req->answered) {
        char detail[128];
        snprintf(detail, sizeof detail, "the implementation gave no answer to %s", req->op);
        emit_error("internal_error", detail);
    } else if (req->result_buf) {
        osdk_json_end_object(&req->result);
        if (req->result.overflow || req->result.depth != 0) emit_error("internal_error", "the answer does not fit its room");
        else emit_line(req->result_buf, req->result.len);
    }
    free(req->result_buf);
    req->result_buf = NULL;
}

/* ---- reading arguments ---------------------------------------------------------------------------- */

static bool bad(okit_request *req, const char *fmt, const char *key)
{
    char detail[256];
    snprintf(detail, sizeof detail, fmt, key);
    okit_error(req, "bad_request", detail);
    return false;
}

const char *okit_op_name(const okit_request *req) { return req->op; }
int okit_profile(const okit_request *req) { return req->profile; }
bool okit_has(const okit_request *req, const char *key) { return jv_get(req->json, key) != NULL; }

bool okit_int(okit_request *req, const char *key, int64_t lo, int64_t hi, int64_t *out)
{
    const jv_t *v = jv_get(req->json, key);
    if (!v) return bad(req, "missing argument '%s'", key);
    if (v->kind == JV_BOOL) return bad(req, "argument '%s' must not be a boolean", key);
    if (v->kind != JV_NUMBER || !v->is_int) return bad(req, "argument '%s' has the wrong type", key);
    if (v->int_overflow || v->i < lo || v->i > hi) return bad(req, "argument '%s' is out of range", key);
    *out = v->i;
    return true;
}

bool okit_bool(okit_request *req, const char *key, bool *out)
{
    const jv_t *v = jv_get(req->json, key);
    if (!v) return bad(req, "missing argument '%s'", key);
    if (v->kind != JV_BOOL) return bad(req, "argument '%s' has the wrong type", key);
    *out = v->boolean;
    return true;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

bool okit_hex(okit_request *req, const char *key, uint8_t **out, size_t *len)
{
    const jv_t *v = jv_get(req->json, key);
    size_t i, n;
    uint8_t *buf;
    if (!v) return bad(req, "missing argument '%s'", key);
    if (v->kind != JV_STRING) return bad(req, "argument '%s' has the wrong type", key);
    if (v->len % 2) return bad(req, "argument '%s' is not a hex string of whole bytes", key);
    n = v->len / 2;
    buf = malloc(n ? n : 1);
    if (!buf) return bad(req, "out of memory reading '%s'", key);
    for (i = 0; i < n; i++) {
        int hi = hexval(v->str[2 * i]), lo = hexval(v->str[2 * i + 1]);
        if (hi < 0 || lo < 0) {
            free(buf);
            return bad(req, "argument '%s' is not a hex string of whole bytes", key);
        }
        buf[i] = (uint8_t)(hi << 4 | lo);
    }
    *out = buf;
    *len = n;
    return true;
}

bool okit_f32(okit_request *req, const char *key, uint32_t *bits)
{
    const jv_t *v = jv_get(req->json, key);
    const jv_t *s;
    size_t i;
    uint32_t x = 0;
    if (!v) return bad(req, "missing argument '%s'", key);
    if (v->kind != JV_OBJECT) return bad(req, "argument '%s' has the wrong type", key);
    s = jv_get(v, "f32");
    if (!s || s->kind != JV_STRING || s->len < 3 || s->len > 10 || s->str[0] != '0' || s->str[1] != 'x')
        return bad(req, "argument '%s' must be {\"f32\": \"0x........\"}", key);
    for (i = 2; i < s->len; i++) {
        int h = hexval(s->str[i]);
        if (h < 0) return bad(req, "argument '%s' must be {\"f32\": \"0x........\"}", key);
        x = x << 4 | (uint32_t)h;
    }
    *bits = x;
    return true;
}

bool okit_sizes(okit_request *req, const char *key, uint64_t **out, size_t *n)
{
    const jv_t *v = jv_get(req->json, key);
    size_t i;
    uint64_t *sizes;
    if (!v) return bad(req, "missing argument '%s'", key);
    if (v->kind != JV_ARRAY) return bad(req, "argument '%s' has the wrong type", key);
    for (i = 0; i < v->count; i++) {
        const jv_t *c = &v->items[i];
        if (c->kind != JV_NUMBER || !c->is_int || c->i < 0)
            return bad(req, "argument '%s' must be a list of non-negative integers", key);
    }
    sizes = malloc(v->count ? v->count * sizeof *sizes : sizeof *sizes);
    if (!sizes) return bad(req, "out of memory reading '%s'", key);
    for (i = 0; i < v->count; i++) sizes[i] = (uint64_t)v->items[i].i;
    *out = sizes;
    *n = v->count;
    return true;
}

/* ---- the loop ------------------------------------------------------------------------------------ */

static const struct {
    const char *name;
    bool profile;    /* a decoding operation: the request names a profile */
} OPERATIONS[] = {
    {"decode_stream", true},          {"decode_frame", true},
    {"decode_payload", true},         {"classify_control_mode", true},
    {"check_movement_control", true}, {"encode_movement_control", false},
    {"encode_frame", false},
};
#define OPERATION_COUNT (sizeof OPERATIONS / sizeof OPERATIONS[0])

/* The callback of OPERATIONS[i]. */
static okit_op callback(const okit_testee *t, size_t i)
{
    switch (i) {
    case 0: return t->decode_stream;
    case 1: return t->decode_frame;
    case 2: return t->decode_payload;
    case 3: return t->classify_control_mode;
    case 4: return t->check_movement_control;
    case 5: return t->encode_movement_control;
    case 6: return t->encode_frame;
    default: return NULL;
    }
}

static void capabilities(okit_request *req)
{
    const okit_testee *t = req->testee;
    osdk_json_t *w = okit_result(req, 4096);
    size_t i;
    if (!w) return;
    osdk_json_begin_object(w);
    osdk_json_key(w, "name");
    osdk_json_string(w, t->name);
    osdk_json_key(w, "operations");
    osdk_json_begin_array(w);
    for (i = 0; i < OPERATION_COUNT; i++)
        if (callback(t, i)) osdk_json_string(w, OPERATIONS[i].name);
    osdk_json_end_array(w);
    osdk_json_key(w, "profiles");
    osdk_json_begin_array(w);
    for (i = 0; t->profiles && t->profiles[i]; i++) osdk_json_string(w, t->profiles[i]);
    osdk_json_end_array(w);
    osdk_json_end_object(w);
}

static int profile_index(const okit_testee *t, const jv_t *prof)
{
    int i;
    if (!prof || prof->kind != JV_STRING || strlen(prof->str) != prof->len) return -1;
    for (i = 0; t->profiles && t->profiles[i]; i++)
        if (strcmp(t->profiles[i], prof->str) == 0) return i;
    return -1;
}

static void answer(const okit_testee *t, const char *line, size_t len)
{
    char err[160];
    jv_t *json = jv_parse(line, len, err, sizeof err);
    const jv_t *op;
    okit_request req;
    size_t i;
    if (!json) {
        char detail[200];
        snprintf(detail, sizeof detail, "not JSON: %s", err);
        emit_error("bad_request", detail);
        return;
    }
    op = jv_get(json, "op");
    if (json->kind != JV_OBJECT || !op || op->kind != JV_STRING) {
        emit_error("bad_request", "a request is a JSON object with an \"op\" string");
        jv_free(json);
        return;
    }
    memset(&req, 0, sizeof req);
    req.testee = t;
    req.json = json;
    req.op = op->str;
    req.profile = -1;
    if (strcmp(op->str, "capabilities") == 0) {
        capabilities(&req);
    } else {
        for (i = 0; i < OPERATION_COUNT && strcmp(OPERATIONS[i].name, op->str) != 0; i++) {
        }
        if (i < OPERATION_COUNT && OPERATIONS[i].profile) req.profile = profile_index(t, jv_get(json, "profile"));
        if (i == OPERATION_COUNT || !callback(t, i) || (OPERATIONS[i].profile && req.profile < 0))
            okit_unsupported(&req);
        else
            callback(t, i)(&req);
    }
    finish(&req);
    jv_free(json);
}

static bool blank(const char *line, size_t len)
{
    size_t k;
    for (k = 0; k < len; k++)
        if (line[k] != ' ' && line[k] != '\t' && line[k] != '\r') return false;
    return true;
}

int okit_main(const okit_testee *t, int argc, char **argv)
{
    char *line = NULL;
    size_t cap = 0, len;
    int c;
    if (argc > 1) {
        if (t->bench) return t->bench(argc, argv);
        fprintf(stderr, "%s: no arguments expected (requests come on stdin, conformance/PROTOCOL.md)\n", t->name);
        return 2;
    }
    for (;;) {
        len = 0;   /* one line of any length */
        while ((c = getchar()) != EOF && c != '\n') {
            if (len + 1 >= cap) {
                size_t ncap = cap ? cap * 2 : 4096;
                char *grown = realloc(line, ncap);
                if (!grown) {
                    free(line);
                    fprintf(stderr, "%s: out of memory reading a request\n", t->name);
                    return 1;
                }
                line = grown;
                cap = ncap;
            }
            line[len++] = (char)c;
        }
        if (len > 0 && !blank(line, len)) answer(t, line, len);
        if (c == EOF) break;
    }
    free(line);
    return 0;
}
