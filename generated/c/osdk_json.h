/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_json.h - a JSON writer into a caller-supplied char buffer (no heap,
 * libc only: memcpy, strlen, snprintf), with the value model's forms of
 * docs/VALUE-MODEL.md for what is not plain JSON: floats as {"f32"/"f64":
 * IEEE bits hex, "value"}, enums as {"value", "name"}, bytes as lowercase
 * hex. It needs nothing else of the generated decoder, so a testee that
 * wraps another implementation (conformance/testee-kit/c) writes its
 * answers with it too.
 *
 * A writer that runs out of room sets `overflow` and writes nothing more;
 * the text written so far stays NUL-terminated.
 */
#ifndef OSDK_JSON_H
#define OSDK_JSON_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OSDK_JSON_MAX_DEPTH 64

typedef struct {
    char *buf;
    size_t cap;
    size_t len;
    bool overflow;
    bool after_key;
    unsigned depth;
    bool first[OSDK_JSON_MAX_DEPTH];
} osdk_json_t;

void osdk_json_init(osdk_json_t *w, char *buf, size_t cap);
/* Append text as is (no separators). */
void osdk_json_raw(osdk_json_t *w, const char *text);
void osdk_json_raw_n(osdk_json_t *w, const char *text, size_t n);
void osdk_json_begin_object(osdk_json_t *w);
void osdk_json_end_object(osdk_json_t *w);
void osdk_json_begin_array(osdk_json_t *w);
void osdk_json_end_array(osdk_json_t *w);
void osdk_json_key(osdk_json_t *w, const char *key);
void osdk_json_string(osdk_json_t *w, const char *s);
void osdk_json_int(osdk_json_t *w, int64_t v);
void osdk_json_uint(osdk_json_t *w, uint64_t v);
void osdk_json_bool(osdk_json_t *w, bool v);
void osdk_json_null(osdk_json_t *w);
void osdk_json_hex(osdk_json_t *w, const uint8_t *p, size_t n);
void osdk_json_enum(osdk_json_t *w, int64_t value, const char *name);
void osdk_json_f32(osdk_json_t *w, uint32_t bits);
void osdk_json_f64(osdk_json_t *w, uint64_t bits);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_JSON_H */
