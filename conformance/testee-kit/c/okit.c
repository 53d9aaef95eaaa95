/*
 * okit.c - see okit.h. The loop, the argument readers and the answers of
 * conformance/PROTOCOL.md, written once for every C or C++ testee.
 */
#include "okit.h"

#include <stdio.h>
#include <string.h>
#ifndef OKIT_PORT
#include <stdlib.h>
#endif

#include "jsonread.h"

struct okit_request {
    const okit_testee *testee;
    jv_t json;
    char op[64];        /* the op, cut to fit (only for messages past the operation table) */
    int profile;
    bool answered;
    char *result_buf;   /* okit_result's buffer, written out when the callback returns */
    osdk_json_t result;
};

/* ---- memory and the line's two ends: the heap and stdio, or (OKIT_PORT) static buffers and the port ---- */

#ifdef OKIT_PORT
static char g_line[OKIT_LINE_MAX];
static char g_answer[OKIT_ANSWER_MAX];
/* arguments of one request; emptied before the next */
static uint64_t g_arena[OKIT_ARENA_MAX / sizeof(uint64_t)];
static size_t g_arena_used;

static void *arg_alloc(size_t n)
{
    size_t words = n ? (n + sizeof(uint64_t) - 1) / sizeof(uint64_t) : 1;
    if (words > sizeof g_arena / sizeof g_arena[0] - g_arena_used) return NULL;
    g_arena_used += words;
    return g_arena + (g_arena_used - words);
}

void okit_free(void *p) { (void)p; }
/* the answer's buffer: what it may need, up to what the board has */
static char *answer_alloc(size_t *cap)
{
    if (*cap > sizeof g_answer) *cap = sizeof g_answer;
    return g_answer;
}
static void answer_free(char *p) { (void)p; }
static void log_line(const char *text) { (void)text; }

static void emit_line(const char *text, size_t n)
{
    okit_port_write(text, n);
    okit_port_write("\n", 1);
}
#else
static void *arg_alloc(size_t n) { return malloc(n ? n : sizeof(uint64_t)); }
void okit_free(void *p) { free(p); }
static char *answer_alloc(size_t *cap) { return malloc(*cap); }
static void answer_free(char *p) { free(p); }
static void log_line(const char *text) { fprintf(stderr, "okit: %s\n", text); }

static void emit_line(const char *text, size_t n)
{
    fwrite(text, 1, n, stdout);
    fputc('\n', stdout);
    fflush(stdout);
}
#endif

/* ---- writing answers ------------------------------------------------------------------------- */

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
        char text[128];
        snprintf(text, sizeof text, "a second answer to one %s request was dropped", req->op);
        log_line(text);
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
    size_t cap = room + 64;
    if (!first_answer(req)) return NULL;
    req->result_buf = answer_alloc(&cap);
    if (!req->result_buf) {
        emit_error("internal_error", "out of memory for the answer");
        return NULL;
    }
    osdk_json_init(&req->result, req->result_buf, cap);
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
    answer_free(req->result_buf);
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
bool okit_has(const okit_request *req, const char *key)
{
    jv_t v;
    return jv_get(&req->json, key, &v);
}

static bool missing(okit_request *req, const char *key, jv_t *v)
{
    if (jv_get(&req->json, key, v)) return false;
    bad(req, "missing argument '%s'", key);
    return true;
}

static bool no_room(okit_request *req, const char *key)
{
    char detail[160];
    snprintf(detail, sizeof detail, "argument '%s' does not fit in the testee's memory", key);
    okit_error(req, "internal_error", detail);
    return false;
}

bool okit_int(okit_request *req, const char *key, int64_t lo, int64_t hi, int64_t *out)
{
    jv_t v;
    int64_t i;
    bool overflow;
    if (missing(req, key, &v)) return false;
    if (v.kind == JV_BOOL) return bad(req, "argument '%s' must not be a boolean", key);
    if (!jv_integer(&v, &i, &overflow)) return bad(req, "argument '%s' has the wrong type", key);
    if (overflow || i < lo || i > hi) return bad(req, "argument '%s' is out of range", key);
    *out = i;
    return true;
}

bool okit_bool(okit_request *req, const char *key, bool *out)
{
    jv_t v;
    if (missing(req, key, &v)) return false;
    if (v.kind != JV_BOOL) return bad(req, "argument '%s' has the wrong type", key);
    *out = v.p[0] == 't';
    return true;
}

static int hexval(unsigned char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

bool okit_hex(okit_request *req, const char *key, uint8_t **out, size_t *len)
{
    jv_t v;
    jv_iter_t it;
    unsigned char hi, lo;
    size_t n = 0;
    uint8_t *buf;
    if (missing(req, key, &v)) return false;
    if (v.kind != JV_STRING) return bad(req, "argument '%s' has the wrong type", key);
    /* the text holds at least two characters per byte: its length bounds the bytes */
    if (!(buf = arg_alloc(v.n / 2))) return no_room(req, key);
    jv_chars(&v, &it);
    while (jv_next_byte(&it, &hi)) {
        if (!jv_next_byte(&it, &lo) || hexval(hi) < 0 || hexval(lo) < 0) {
            okit_free(buf);
            return bad(req, "argument '%s' is not a hex string of whole bytes", key);
        }
        buf[n++] = (uint8_t)(hexval(hi) << 4 | hexval(lo));
    }
    *out = buf;
    *len = n;
    return true;
}

bool okit_f32(okit_request *req, const char *key, uint32_t *bits)
{
    jv_t v, s;
    jv_iter_t it;
    unsigned char c;
    size_t digits = 0;
    uint32_t x = 0;
    if (missing(req, key, &v)) return false;
    if (v.kind != JV_OBJECT) return bad(req, "argument '%s' has the wrong type", key);
    if (!jv_get(&v, "f32", &s) || s.kind != JV_STRING) goto malformed;
    jv_chars(&s, &it);
    if (!jv_next_byte(&it, &c) || c != '0' || !jv_next_byte(&it, &c) || c != 'x') goto malformed;
    while (jv_next_byte(&it, &c)) {
        if (hexval(c) < 0 || ++digits > 8) goto malformed;
        x = x << 4 | (uint32_t)hexval(c);
    }
    if (digits == 0) goto malformed;
    *bits = x;
    return true;
malformed:
    return bad(req, "argument '%s' must be {\"f32\": \"0x........\"}", key);
}

bool okit_sizes(okit_request *req, const char *key, uint64_t **out, size_t *n)
{
    jv_t v, item;
    jv_iter_t it;
    size_t count = 0, i = 0;
    uint64_t *sizes;
    if (missing(req, key, &v)) return false;
    if (v.kind != JV_ARRAY) return bad(req, "argument '%s' has the wrong type", key);
    jv_items(&v, &it);
    while (jv_next_item(&it, &item)) {
        int64_t x;
        bool overflow;
        if (!jv_integer(&item, &x, &overflow) || x < 0)
            return bad(req, "argument '%s' must be a list of non-negative integers", key);
        count++;
    }
    if (!(sizes = arg_alloc(count * sizeof *sizes))) return no_room(req, key);
    jv_items(&v, &it);
    while (jv_next_item(&it, &item)) {
        int64_t x;
        bool overflow;
        jv_integer(&item, &x, &overflow);
        sizes[i++] = (uint64_t)x;
    }
    *out = sizes;
    *n = count;
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

static int profile_index(const okit_testee *t, const jv_t *json)
{
    jv_t prof;
    int i;
    if (!jv_get(json, "profile", &prof)) return -1;
    for (i = 0; t->profiles && t->profiles[i]; i++)
        if (jv_string_is(&prof, t->profiles[i])) return i;
    return -1;
}

static void answer(const okit_testee *t, const char *line, size_t len)
{
    char err[160];
    jv_t json, op;
    okit_request req;
    size_t i;
    if (!jv_parse(line, len, &json, err, sizeof err)) {
        char detail[200];
        snprintf(detail, sizeof detail, "not JSON: %s", err);
        emit_error("bad_request", detail);
        return;
    }
    if (json.kind != JV_OBJECT || !jv_get(&json, "op", &op) || op.kind != JV_STRING) {
        emit_error("bad_request", "a request is a JSON object with an \"op\" string");
        return;
    }
    memset(&req, 0, sizeof req);
    req.testee = t;
    req.json = json;
    if (!jv_string_copy(&op, req.op, sizeof req.op)) strcpy(req.op, "(a long or odd op)");
    req.profile = -1;
#ifdef OKIT_PORT
    g_arena_used = 0;
#endif
    if (jv_string_is(&op, "capabilities")) {
        capabilities(&req);
    } else {
        for (i = 0; i < OPERATION_COUNT && !jv_string_is(&op, OPERATIONS[i].name); i++) {
        }
        if (i < OPERATION_COUNT && OPERATIONS[i].profile) req.profile = profile_index(t, &json);
        if (i == OPERATION_COUNT || !callback(t, i) || (OPERATIONS[i].profile && req.profile < 0))
            okit_unsupported(&req);
        else
            callback(t, i)(&req);
    }
    finish(&req);
}

static bool blank(const char *line, size_t len)
{
    size_t k;
    for (k = 0; k < len; k++)
        if (line[k] != ' ' && line[k] != '\t' && line[k] != '\r') return false;
    return true;
}

#ifdef OKIT_PORT
int okit_main(const okit_testee *t, int argc, char **argv)
{
    (void)argc;
    (void)argv;
    for (;;) {
        size_t len = 0;
        bool cut = false;
        int c;
        while ((c = okit_port_getc()) >= 0 && c != '\n') {
            if (len < sizeof g_line) g_line[len++] = (char)c;
            else cut = true;
        }
        if (cut) {
            char detail[96];
            snprintf(detail, sizeof detail, "a request longer than the testee's %u-byte line", (unsigned)sizeof g_line);
            emit_error("internal_error", detail);
        } else if (len > 0 && !blank(g_line, len)) {
            answer(t, g_line, len);
        }
        if (c < 0) return 0;
    }
}
#else
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
#endif
