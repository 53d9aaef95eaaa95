/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_json.c - see osdk_json.h. */
#include "osdk_json.h"

#include <stdio.h>
#include <string.h>

void osdk_json_init(osdk_json_t *w, char *buf, size_t cap)
{
    memset(w, 0, sizeof *w);
    w->buf = buf;
    w->cap = cap;
    w->first[0] = true;
    if (buf && cap) buf[0] = '\0';
    else w->overflow = true;
}

void osdk_json_raw_n(osdk_json_t *w, const char *text, size_t n)
{
    if (w->overflow) return;
    if (w->cap - w->len <= n) {
        w->overflow = true;
        return;
    }
    memcpy(w->buf + w->len, text, n);
    w->len += n;
    w->buf[w->len] = '\0';
}

void osdk_json_raw(osdk_json_t *w, const char *text)
{
    osdk_json_raw_n(w, text, strlen(text));
}

/* The separator before a value or a key. */
static void sep(osdk_json_t *w)
{
    if (w->after_key) {
        w->after_key = false;
        return;
    }
    if (w->depth > 0) {
        if (!w->first[w->depth]) osdk_json_raw_n(w, ",", 1);
        w->first[w->depth] = false;
    }
}

static void open_(osdk_json_t *w, const char *c)
{
    sep(w);
    osdk_json_raw_n(w, c, 1);
    if (w->depth + 1 >= OSDK_JSON_MAX_DEPTH) {
        w->overflow = true;
        return;
    }
    w->depth++;
    w->first[w->depth] = true;
}

static void close_(osdk_json_t *w, const char *c)
{
    if (w->depth > 0) w->depth--;
    osdk_json_raw_n(w, c, 1);
}

void osdk_json_begin_object(osdk_json_t *w) { open_(w, "{"); }
void osdk_json_end_object(osdk_json_t *w) { close_(w, "}"); }
void osdk_json_begin_array(osdk_json_t *w) { open_(w, "["); }
void osdk_json_end_array(osdk_json_t *w) { close_(w, "]"); }

static void quoted(osdk_json_t *w, const char *s)
{
    static const char hexd[] = "0123456789abcdef";
    osdk_json_raw_n(w, "\"", 1);
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\') {
            char e[2];
            e[0] = '\\';
            e[1] = (char)ch;
            osdk_json_raw_n(w, e, 2);
        } else if (ch < 0x20) {
            char e[6] = {'\\', 'u', '0', '0', 0, 0};
            e[4] = hexd[ch >> 4];
            e[5] = hexd[ch & 15];
            osdk_json_raw_n(w, e, 6);
        } else {
            osdk_json_raw_n(w, (const char *)&ch, 1);
        }
    }
    osdk_json_raw_n(w, "\"", 1);
}

void osdk_json_key(osdk_json_t *w, const char *key)
{
    sep(w);
    quoted(w, key);
    osdk_json_raw_n(w, ":", 1);
    w->after_key = true;
}

void osdk_json_string(osdk_json_t *w, const char *s)
{
    sep(w);
    quoted(w, s);
}

void osdk_json_int(osdk_json_t *w, int64_t v)
{
    char tmp[32];
    sep(w);
    snprintf(tmp, sizeof tmp, "%lld", (long long)v);
    osdk_json_raw(w, tmp);
}

void osdk_json_uint(osdk_json_t *w, uint64_t v)
{
    char tmp[32];
    sep(w);
    snprintf(tmp, sizeof tmp, "%llu", (unsigned long long)v);
    osdk_json_raw(w, tmp);
}

void osdk_json_bool(osdk_json_t *w, bool v)
{
    sep(w);
    osdk_json_raw(w, v ? "true" : "false");
}

void osdk_json_null(osdk_json_t *w)
{
    sep(w);
    osdk_json_raw(w, "null");
}

void osdk_json_hex(osdk_json_t *w, const uint8_t *p, size_t n)
{
    static const char hexd[] = "0123456789abcdef";
    size_t i;
    sep(w);
    osdk_json_raw_n(w, "\"", 1);
    for (i = 0; i < n; i++) {
        char two[2];
        two[0] = hexd[p[i] >> 4];
        two[1] = hexd[p[i] & 15];
        osdk_json_raw_n(w, two, 2);
    }
    osdk_json_raw_n(w, "\"", 1);
}

void osdk_json_enum(osdk_json_t *w, int64_t value, const char *name)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "value");
    osdk_json_int(w, value);
    osdk_json_key(w, "name");
    if (name) osdk_json_string(w, name);
    else osdk_json_null(w);
    osdk_json_end_object(w);
}

/* The float whose IEEE-754 bits these are (memcpy: no aliasing, no conversion on the way). */
static float f32_of(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

static double f64_of(uint64_t bits)
{
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}

/* "value" of a float: a number, -0.0 as -0.0, else "NaN"/"Infinity"/"-Infinity". */
static void float_value(osdk_json_t *w, double v, int is_nan, int is_inf, int negative, int is_zero, int digits)
{
    char tmp[48];
    if (is_nan) {
        osdk_json_string(w, "NaN");
        return;
    }
    if (is_inf) {
        osdk_json_string(w, negative ? "-Infinity" : "Infinity");
        return;
    }
    sep(w);
    if (is_zero) {
        osdk_json_raw(w, negative ? "-0.0" : "0.0");
        return;
    }
    snprintf(tmp, sizeof tmp, "%.*g", digits, v);
    if (strpbrk(tmp, ".e") == NULL) {
        size_t n = strlen(tmp);
        if (n + 2 < sizeof tmp) {
            tmp[n] = '.';
            tmp[n + 1] = '0';
            tmp[n + 2] = '\0';
        }
    }
    osdk_json_raw(w, tmp);
}

void osdk_json_f32(osdk_json_t *w, uint32_t bits)
{
    char tmp[16];
    unsigned exp = (bits >> 23) & 0xffu;
    uint32_t mant = bits & 0x7fffffu;
    osdk_json_begin_object(w);
    osdk_json_key(w, "f32");
    snprintf(tmp, sizeof tmp, "0x%08lx", (unsigned long)bits);
    osdk_json_string(w, tmp);
    osdk_json_key(w, "value");
    float_value(w, (double)f32_of(bits), exp == 0xffu && mant != 0, exp == 0xffu && mant == 0,
                (int)(bits >> 31), (bits & 0x7fffffffu) == 0, 9);
    osdk_json_end_object(w);
}

void osdk_json_f64(osdk_json_t *w, uint64_t bits)
{
    char tmp[24];
    unsigned exp = (unsigned)((bits >> 52) & 0x7ffu);
    uint64_t mant = bits & ((UINT64_C(1) << 52) - 1u);
    osdk_json_begin_object(w);
    osdk_json_key(w, "f64");
    snprintf(tmp, sizeof tmp, "0x%016llx", (unsigned long long)bits);
    osdk_json_string(w, tmp);
    osdk_json_key(w, "value");
    float_value(w, f64_of(bits), exp == 0x7ffu && mant != 0, exp == 0x7ffu && mant == 0,
                (int)(bits >> 63), (bits & ~(UINT64_C(1) << 63)) == 0, 17);
    osdk_json_end_object(w);
}
