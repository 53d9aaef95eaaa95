/* jsonread.c - see jsonread.h. */
#include "jsonread.h"

#include <stdio.h>
#include <string.h>

/* ---- checking ------------------------------------------------------------------------------ */

typedef struct {
    const char *start;
    const char *p;
    const char *end;
    char *err;
    size_t errcap;
    bool failed;
} reader_t;

static bool fail(reader_t *r, const char *msg)
{
    if (!r->failed && r->err && r->errcap)
        snprintf(r->err, r->errcap, "%s at byte %lu", msg, (unsigned long)(r->p - r->start));
    r->failed = true;
    return false;
}

static bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

static void skip_ws(reader_t *r)
{
    while (r->p < r->end && is_ws(*r->p)) r->p++;
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

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* At the opening quote; on success just after the closing one. */
static bool check_string(reader_t *r)
{
    r->p++;
    while (r->p < r->end && *r->p != '"') {
        unsigned char c = (unsigned char)*r->p;
        if (c < 0x20) return fail(r, "control character in string");
        r->p++;
        if (c != '\\') continue;
        if (r->p >= r->end) break;
        c = (unsigned char)*r->p++;
        if (c == 'u') {
            int k;
            for (k = 0; k < 4; k++)
                if (r->p + k >= r->end || hexval(r->p[k]) < 0) return fail(r, "bad \\u escape");
            r->p += 4;
        } else if (!strchr("\"\\/bfnrt", c) || c == '\0') {
            return fail(r, "bad escape");
        }
    }
    if (r->p >= r->end) return fail(r, "unterminated string");
    r->p++;
    return true;
}

static bool digits(reader_t *r)
{
    if (r->p >= r->end || !(*r->p >= '0' && *r->p <= '9')) return false;
    while (r->p < r->end && *r->p >= '0' && *r->p <= '9') r->p++;
    return true;
}

static bool check_number(reader_t *r)
{
    if (r->p < r->end && *r->p == '-') r->p++;
    if (r->p < r->end && *r->p == '0') r->p++;
    else if (!digits(r)) return fail(r, "bad number");
    if (r->p < r->end && *r->p == '.') {
        r->p++;
        if (!digits(r)) return fail(r, "bad number");
    }
    if (r->p < r->end && (*r->p == 'e' || *r->p == 'E')) {
        r->p++;
        if (r->p < r->end && (*r->p == '+' || *r->p == '-')) r->p++;
        if (!digits(r)) return fail(r, "bad number");
    }
    return true;
}

static bool check_scalar(reader_t *r)
{
    switch (*r->p) {
    case '"': return check_string(r);
    case 't': if (literal(r, "true")) return true; break;
    case 'f': if (literal(r, "false")) return true; break;
    case 'n': if (literal(r, "null")) return true; break;
    case 'N': if (literal(r, "NaN")) return true; break;  /* Python's json writes these */
    case 'I': if (literal(r, "Infinity")) return true; break;
    default:
        if (*r->p == '-' && literal(r, "-Infinity")) return true;
        if (*r->p == '-' || (*r->p >= '0' && *r->p <= '9')) return check_number(r);
        break;
    }
    return fail(r, "unexpected character");
}

static jv_kind_t kind_at(char c)
{
    switch (c) {
    case '{': return JV_OBJECT;
    case '[': return JV_ARRAY;
    case '"': return JV_STRING;
    case 't': case 'f': return JV_BOOL;
    case 'n': return JV_NULL;
    default: return JV_NUMBER;
    }
}

/* After an object's '{' or ',': a key, its ':', and whitespace up to the value. */
static bool member_key(reader_t *r)
{
    skip_ws(r);
    if (r->p >= r->end || *r->p != '"') return fail(r, "expected a key");
    if (!check_string(r)) return false;
    skip_ws(r);
    if (r->p >= r->end || *r->p != ':') return fail(r, "expected :");
    r->p++;
    return true;
}

bool jv_parse(const char *text, size_t len, jv_t *out, char *err, size_t errcap)
{
    /* the open containers as a bit stack (1: object), so nesting costs no recursion */
    unsigned char open[JV_MAX_DEPTH / 8 + 1];
    unsigned depth = 0;
    const char *first;
    reader_t r;
    r.start = r.p = text;
    r.end = text + len;
    r.err = err;
    r.errcap = errcap;
    r.failed = false;
    if (err && errcap) err[0] = '\0';
    skip_ws(&r);
    first = r.p;
    for (;;) {
        /* a value */
        skip_ws(&r);
        if (depth > JV_MAX_DEPTH) return fail(&r, "nested too deeply");
        if (r.p >= r.end) return fail(&r, "unexpected end");
        if (*r.p == '{' || *r.p == '[') {
            bool object = *r.p == '{';
            if (depth == JV_MAX_DEPTH) return fail(&r, "nested too deeply");
            if (object) open[depth / 8] |= (unsigned char)(1u << depth % 8);
            else open[depth / 8] &= (unsigned char)~(1u << depth % 8);
            depth++;
            r.p++;
            skip_ws(&r);
            if (r.p < r.end && *r.p == (object ? '}' : ']')) {
                r.p++;
                depth--;
            } else {
                if (object && !member_key(&r)) return false;
                continue;
            }
        } else if (!check_scalar(&r)) {
            return false;
        }
        /* after a value: close what it ends, or go on to the next item */
        for (;;) {
            bool object;
            if (depth == 0) {
                const char *last = r.p;
                skip_ws(&r);
                if (r.p != r.end) return fail(&r, "extra data after the value");
                out->kind = kind_at(*first);
                out->p = first;
                out->n = (size_t)(last - first);
                return true;
            }
            object = (open[(depth - 1) / 8] >> (depth - 1) % 8) & 1u;
            skip_ws(&r);
            if (r.p < r.end && *r.p == ',') {
                r.p++;
                if (object && !member_key(&r)) return false;
                break;
            }
            if (r.p < r.end && *r.p == (object ? '}' : ']')) {
                r.p++;
                depth--;
                continue;
            }
            return fail(&r, object ? "expected , or }" : "expected , or ]");
        }
    }
}

/* ---- reading checked text -------------------------------------------------------------------- */

static const char *skip_ws_in(const char *p, const char *end)
{
    while (p < end && is_ws(*p)) p++;
    return p;
}

/* Just after the string or value starting at p (the text is known to be valid). */
static const char *string_end(const char *p, const char *end)
{
    p++;
    while (p < end && *p != '"') p += *p == '\\' ? 2 : 1;
    return p + 1;
}

static const char *value_end(const char *p, const char *end)
{
    size_t nest = 0;
    if (*p == '"') return string_end(p, end);
    if (*p != '{' && *p != '[') {
        while (p < end && !is_ws(*p) && *p != ',' && *p != ']' && *p != '}') p++;
        return p;
    }
    while (p < end) {
        if (*p == '"') {
            p = string_end(p, end);
            continue;
        }
        if (*p == '{' || *p == '[') nest++;
        else if (*p == '}' || *p == ']') {
            if (--nest == 0) return p + 1;
        }
        p++;
    }
    return p;
}

static void value_at(const char *p, const char *end, jv_t *out)
{
    out->kind = kind_at(*p);
    out->p = p;
    out->n = (size_t)(value_end(p, end) - p);
}

bool jv_get(const jv_t *obj, const char *key, jv_t *out)
{
    const char *p, *end;
    bool found = false;
    if (obj == NULL || obj->kind != JV_OBJECT) return false;
    p = obj->p + 1;
    end = obj->p + obj->n - 1;
    for (;;) {
        jv_t k, v;
        p = skip_ws_in(p, end);
        if (p >= end) return found;
        value_at(p, end, &k);
        p = skip_ws_in(k.p + k.n, end) + 1; /* the ':' */
        p = skip_ws_in(p, end);
        value_at(p, end, &v);
        if (jv_string_is(&k, key)) {
            *out = v;
            found = true;
        }
        p = skip_ws_in(v.p + v.n, end);
        if (p < end && *p == ',') p++;
    }
}

bool jv_integer(const jv_t *v, int64_t *i, bool *overflow)
{
    const char *p = v->p, *end = v->p + v->n;
    bool negative = false;
    uint64_t mag = 0, limit;
    if (v->kind != JV_NUMBER || p >= end) return false;
    if (*p == '-') {
        negative = true;
        p++;
    }
    if (p >= end || !(*p >= '0' && *p <= '9')) return false; /* NaN, Infinity */
    limit = negative ? (uint64_t)INT64_MAX + 1u : (uint64_t)INT64_MAX;
    *overflow = false;
    for (; p < end; p++) {
        unsigned d;
        if (!(*p >= '0' && *p <= '9')) return false; /* a fraction or an exponent */
        d = (unsigned)(*p - '0');
        if (mag > (limit - d) / 10u) {
            *overflow = true;
            mag = limit;
        } else if (!*overflow) {
            mag = mag * 10u + d;
        }
    }
    if (negative) *i = mag == (uint64_t)INT64_MAX + 1u ? INT64_MIN : -(int64_t)mag;
    else *i = (int64_t)mag;
    return true;
}

void jv_items(const jv_t *arr, jv_iter_t *it)
{
    it->p = arr->p + 1;
    it->end = arr->p + arr->n - 1;
    it->npending = 0;
}

bool jv_next_item(jv_iter_t *it, jv_t *item)
{
    const char *p = skip_ws_in(it->p, it->end);
    if (p >= it->end) return false;
    value_at(p, it->end, item);
    p = skip_ws_in(item->p + item->n, it->end);
    if (p < it->end && *p == ',') p++;
    it->p = p;
    return true;
}

void jv_chars(const jv_t *str, jv_iter_t *it)
{
    it->p = str->p + 1;
    it->end = str->p + str->n - 1;
    it->npending = 0;
}

static unsigned read_u4(const char *p)
{
    unsigned v = 0;
    int k;
    for (k = 0; k < 4; k++) v = v << 4 | (unsigned)hexval(p[k]);
    return v;
}

/* UTF-8 of a code point; the first byte returned, the others queued in the iterator. */
static unsigned char queue_utf8(jv_iter_t *it, unsigned long cp)
{
    unsigned char b[4];
    unsigned n, k;
    if (cp < 0x80) {
        b[0] = (unsigned char)cp;
        n = 1;
    } else if (cp < 0x800) {
        b[0] = (unsigned char)(0xC0 | (cp >> 6));
        b[1] = (unsigned char)(0x80 | (cp & 0x3F));
        n = 2;
    } else if (cp < 0x10000) {
        b[0] = (unsigned char)(0xE0 | (cp >> 12));
        b[1] = (unsigned char)(0x80 | ((cp >> 6) & 0x3F));
        b[2] = (unsigned char)(0x80 | (cp & 0x3F));
        n = 3;
    } else {
        b[0] = (unsigned char)(0xF0 | (cp >> 18));
        b[1] = (unsigned char)(0x80 | ((cp >> 12) & 0x3F));
        b[2] = (unsigned char)(0x80 | ((cp >> 6) & 0x3F));
        b[3] = (unsigned char)(0x80 | (cp & 0x3F));
        n = 4;
    }
    it->npending = n - 1;
    for (k = 1; k < n; k++) it->pending[n - 1 - k] = b[k]; /* popped from the end */
    return b[0];
}

bool jv_next_byte(jv_iter_t *it, unsigned char *byte)
{
    unsigned char c;
    if (it->npending) {
        *byte = it->pending[--it->npending];
        return true;
    }
    if (it->p >= it->end) return false;
    c = (unsigned char)*it->p++;
    if (c != '\\') {
        *byte = c;
        return true;
    }
    c = (unsigned char)*it->p++;
    switch (c) {
    case 'b': *byte = '\b'; return true;
    case 'f': *byte = '\f'; return true;
    case 'n': *byte = '\n'; return true;
    case 'r': *byte = '\r'; return true;
    case 't': *byte = '\t'; return true;
    case 'u': {
        unsigned long cp = read_u4(it->p);
        it->p += 4;
        if (cp >= 0xD800 && cp < 0xDC00 && it->end - it->p >= 6 && it->p[0] == '\\' && it->p[1] == 'u') {
            unsigned lo = read_u4(it->p + 2);
            if (lo >= 0xDC00 && lo < 0xE000) {
                cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                it->p += 6;
            }
        }
        *byte = queue_utf8(it, cp);
        return true;
    }
    default: *byte = c; return true; /* '"', '\\', '/' */
    }
}

bool jv_string_is(const jv_t *str, const char *text)
{
    jv_iter_t it;
    unsigned char c;
    if (str->kind != JV_STRING) return false;
    jv_chars(str, &it);
    while (jv_next_byte(&it, &c))
        if (*text == '\0' || (unsigned char)*text++ != c) return false;
    return *text == '\0';
}

bool jv_string_copy(const jv_t *str, char *out, size_t cap)
{
    jv_iter_t it;
    unsigned char c;
    size_t n = 0;
    if (str->kind != JV_STRING || cap == 0) return false;
    jv_chars(str, &it);
    while (jv_next_byte(&it, &c)) {
        if (c == '\0' || n + 1 >= cap) return false;
        out[n++] = (char)c;
    }
    out[n] = '\0';
    return true;
}
