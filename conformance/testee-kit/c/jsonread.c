/* jsonread.c - see jsonread.h. */
#include "jsonread.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *p;
    const char *end;
    char *err;
    size_t errcap;
    bool failed;
} reader_t;

static void fail(reader_t *r, const char *msg)
{
    if (!r->failed && r->err && r->errcap) snprintf(r->err, r->errcap, "%s at byte %ld", msg, (long)(r->end - r->p));
    r->failed = true;
}

static void skip_ws(reader_t *r)
{
    while (r->p < r->end && (*r->p == ' ' || *r->p == '\t' || *r->p == '\n' || *r->p == '\r')) r->p++;
}

static bool literal(reader_t *r, const char *word)
{
    size_t n = strlen(word);
    if ((size_t)(r->end - r->p) >= n && memcmp(r->p, word, n) == 0) {
        r->p += n;
        return true;
    }
    return false;
}

static void free_inner(jv_t *v)
{
    size_t i;
    if (v == NULL) return;
    free(v->str);
    if (v->items) {
        for (i = 0; i < v->count; i++) free_inner(&v->items[i]);
        free(v->items);
    }
    if (v->keys) {
        for (i = 0; i < v->count; i++) free(v->keys[i]);
        free(v->keys);
    }
    memset(v, 0, sizeof *v);
}

void jv_free(jv_t *v)
{
    if (v == NULL) return;
    free_inner(v);
    free(v);
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

static bool read_u4(reader_t *r, unsigned *out)
{
    unsigned v = 0;
    int k;
    if (r->end - r->p < 4) return false;
    for (k = 0; k < 4; k++) {
        int h = hexval(r->p[k]);
        if (h < 0) return false;
        v = v << 4 | (unsigned)h;
    }
    r->p += 4;
    *out = v;
    return true;
}

static size_t put_utf8(char *dst, unsigned long cp)
{
    if (cp < 0x80) {
        dst[0] = (char)cp;
        return 1;
    }
    if (cp < 0x800) {
        dst[0] = (char)(0xC0 | (cp >> 6));
        dst[1] = (char)(0x80 | (cp & 0x3F));
        return 2;
    }
    if (cp < 0x10000) {
        dst[0] = (char)(0xE0 | (cp >> 12));
        dst[1] = (char)(0x80 | ((cp >> 6) & 0x3F));
        dst[2] = (char)(0x80 | (cp & 0x3F));
        return 3;
    }
    dst[0] = (char)(0xF0 | (cp >> 18));
    dst[1] = (char)(0x80 | ((cp >> 12) & 0x3F));
    dst[2] = (char)(0x80 | ((cp >> 6) & 0x3F));
    dst[3] = (char)(0x80 | (cp & 0x3F));
    return 4;
}

/* After the opening quote. Escapes only shrink text, so the raw length bounds the result. */
static char *read_string(reader_t *r, size_t *outlen)
{
    const char *start = r->p;
    const char *q = start;
    char *buf, *o;
    while (q < r->end && *q != '"') {
        if (*q == '\\') q++;
        q++;
    }
    if (q >= r->end) {
        fail(r, "unterminated string");
        return NULL;
    }
    buf = malloc((size_t)(q - start) + 1);
    if (!buf) {
        fail(r, "out of memory");
        return NULL;
    }
    o = buf;
    while (r->p < r->end && *r->p != '"') {
        unsigned char c = (unsigned char)*r->p++;
        if (c < 0x20) {
            fail(r, "control character in string");
            free(buf);
            return NULL;
        }
        if (c != '\\') {
            *o++ = (char)c;
            continue;
        }
        if (r->p >= r->end) break;
        c = (unsigned char)*r->p++;
        switch (c) {
        case '"': *o++ = '"'; break;
        case '\\': *o++ = '\\'; break;
        case '/': *o++ = '/'; break;
        case 'b': *o++ = '\b'; break;
        case 'f': *o++ = '\f'; break;
        case 'n': *o++ = '\n'; break;
        case 'r': *o++ = '\r'; break;
        case 't': *o++ = '\t'; break;
        case 'u': {
            unsigned hi, lo;
            unsigned long cp;
            if (!read_u4(r, &hi)) {
                fail(r, "bad \\u escape");
                free(buf);
                return NULL;
            }
            cp = hi;
            if (hi >= 0xD800 && hi < 0xDC00 && r->end - r->p >= 6 && r->p[0] == '\\' && r->p[1] == 'u') {
                const char *save = r->p;
                r->p += 2;
                if (read_u4(r, &lo) && lo >= 0xDC00 && lo < 0xE000) {
                    cp = 0x10000 + (((unsigned long)hi - 0xD800) << 10) + (lo - 0xDC00);
                } else {
                    r->p = save;
                }
            }
            o += put_utf8(o, cp); /* at most 4 bytes for 6 or 12 bytes of escape */
            break;
        }
        default:
            fail(r, "bad escape");
            free(buf);
            return NULL;
        }
    }
    if (r->p >= r->end) {
        fail(r, "unterminated string");
        free(buf);
        return NULL;
    }
    r->p++; /* closing quote */
    *o = '\0';
    *outlen = (size_t)(o - buf);
    return buf;
}

static void read_number(reader_t *r, jv_t *v)
{
    const char *s = r->p;
    bool integer = true;
    char *tmp;
    size_t n;
    if (r->p < r->end && *r->p == '-') r->p++;
    if (r->p >= r->end || !(*r->p >= '0' && *r->p <= '9')) {
        fail(r, "bad number");
        return;
    }
    if (*r->p == '0') {
        r->p++;
    } else {
        while (r->p < r->end && *r->p >= '0' && *r->p <= '9') r->p++;
    }
    if (r->p < r->end && *r->p == '.') {
        integer = false;
        r->p++;
        if (r->p >= r->end || !(*r->p >= '0' && *r->p <= '9')) {
            fail(r, "bad number");
            return;
        }
        while (r->p < r->end && *r->p >= '0' && *r->p <= '9') r->p++;
    }
    if (r->p < r->end && (*r->p == 'e' || *r->p == 'E')) {
        integer = false;
        r->p++;
        if (r->p < r->end && (*r->p == '+' || *r->p == '-')) r->p++;
        if (r->p >= r->end || !(*r->p >= '0' && *r->p <= '9')) {
            fail(r, "bad number");
            return;
        }
        while (r->p < r->end && *r->p >= '0' && *r->p <= '9') r->p++;
    }
    n = (size_t)(r->p - s);
    tmp = malloc(n + 1);
    if (!tmp) {
        fail(r, "out of memory");
        return;
    }
    memcpy(tmp, s, n);
    tmp[n] = '\0';
    v->kind = JV_NUMBER;
    v->is_int = integer;
    v->d = strtod(tmp, NULL);
    if (integer) {
        long long ll;
        errno = 0;
        ll = strtoll(tmp, NULL, 10);
        v->i = (int64_t)ll;
        v->int_overflow = (errno == ERANGE);
    }
    free(tmp);
}

static bool grow(reader_t *r, jv_t *v, size_t *cap, bool with_keys)
{
    if (v->count < *cap) return true;
    {
        size_t ncap = *cap ? *cap * 2 : 4;
        jv_t *items = realloc(v->items, ncap * sizeof *items);
        if (!items) {
            fail(r, "out of memory");
            return false;
        }
        v->items = items;
        memset(items + v->count, 0, (ncap - v->count) * sizeof *items);
        if (with_keys) {
            char **keys = realloc(v->keys, ncap * sizeof *keys);
            if (!keys) {
                fail(r, "out of memory");
                return false;
            }
            v->keys = keys;
            memset(keys + v->count, 0, (ncap - v->count) * sizeof *keys);
        }
        *cap = ncap;
    }
    return true;
}

static void read_value(reader_t *r, jv_t *v, int depth);

static void read_array(reader_t *r, jv_t *v, int depth)
{
    size_t cap = 0;
    v->kind = JV_ARRAY;
    skip_ws(r);
    if (r->p < r->end && *r->p == ']') {
        r->p++;
        return;
    }
    for (;;) {
        if (!grow(r, v, &cap, false)) return;
        read_value(r, &v->items[v->count], depth + 1);
        v->count++;
        if (r->failed) return;
        skip_ws(r);
        if (r->p < r->end && *r->p == ',') {
            r->p++;
            continue;
        }
        if (r->p < r->end && *r->p == ']') {
            r->p++;
            return;
        }
        fail(r, "expected , or ]");
        return;
    }
}

static void read_object(reader_t *r, jv_t *v, int depth)
{
    size_t cap = 0;
    v->kind = JV_OBJECT;
    skip_ws(r);
    if (r->p < r->end && *r->p == '}') {
        r->p++;
        return;
    }
    for (;;) {
        size_t klen;
        char *key;
        skip_ws(r);
        if (r->p >= r->end || *r->p != '"') {
            fail(r, "expected a key");
            return;
        }
        r->p++;
        key = read_string(r, &klen);
        if (!key) return;
        if (!grow(r, v, &cap, true)) {
            free(key);
            return;
        }
        v->keys[v->count] = key;
        skip_ws(r);
        if (r->p >= r->end || *r->p != ':') {
            v->count++;
            fail(r, "expected :");
            return;
        }
        r->p++;
        read_value(r, &v->items[v->count], depth + 1);
        v->count++;
        if (r->failed) return;
        skip_ws(r);
        if (r->p < r->end && *r->p == ',') {
            r->p++;
            continue;
        }
        if (r->p < r->end && *r->p == '}') {
            r->p++;
            return;
        }
        fail(r, "expected , or }");
        return;
    }
}

static void read_value(reader_t *r, jv_t *v, int depth)
{
    if (depth > JV_MAX_DEPTH) {
        fail(r, "nested too deeply");
        return;
    }
    skip_ws(r);
    if (r->p >= r->end) {
        fail(r, "unexpected end");
        return;
    }
    switch (*r->p) {
    case '{':
        r->p++;
        read_object(r, v, depth);
        return;
    case '[':
        r->p++;
        read_array(r, v, depth);
        return;
    case '"':
        r->p++;
        v->kind = JV_STRING;
        v->str = read_string(r, &v->len);
        return;
    case 't':
        if (literal(r, "true")) {
            v->kind = JV_BOOL;
            v->boolean = true;
            return;
        }
        break;
    case 'f':
        if (literal(r, "false")) {
            v->kind = JV_BOOL;
            v->boolean = false;
            return;
        }
        break;
    case 'n':
        if (literal(r, "null")) {
            v->kind = JV_NULL;
            return;
        }
        break;
    case 'N':
        if (literal(r, "NaN")) { /* Python's json accepts these */
            v->kind = JV_NUMBER;
            v->d = 0.0;
            return;
        }
        break;
    case 'I':
        if (literal(r, "Infinity")) {
            v->kind = JV_NUMBER;
            return;
        }
        break;
    default:
        if (*r->p == '-' && literal(r, "-Infinity")) {
            v->kind = JV_NUMBER;
            return;
        }
        if (*r->p == '-' || (*r->p >= '0' && *r->p <= '9')) {
            read_number(r, v);
            return;
        }
        break;
    }
    fail(r, "unexpected character");
}

jv_t *jv_parse(const char *text, size_t len, char *err, size_t errcap)
{
    reader_t r;
    jv_t *v = calloc(1, sizeof *v);
    if (err && errcap) err[0] = '\0';
    if (!v) return NULL;
    r.p = text;
    r.end = text + len;
    r.err = err;
    r.errcap = errcap;
    r.failed = false;
    read_value(&r, v, 0);
    if (!r.failed) {
        skip_ws(&r);
        if (r.p != r.end) fail(&r, "extra data after the value");
    }
    if (r.failed) {
        jv_free(v);
        return NULL;
    }
    return v;
}

const jv_t *jv_get(const jv_t *obj, const char *key)
{
    size_t i;
    const jv_t *found = NULL;
    if (obj == NULL || obj->kind != JV_OBJECT) return NULL;
    for (i = 0; i < obj->count; i++) {
        if (obj->keys[i] && strcmp(obj->keys[i], key) == 0) found = &obj->items[i];
    }
    return found;
}
