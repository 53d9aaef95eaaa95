/*
 * jsonread.h - a small JSON reader for the testee's request lines.
 *
 * It allocates nothing: jv_parse checks that a text is one JSON value and
 * the accessors read values where they lie in that text, so the same reader
 * serves a host process and a microcontroller with no heap (the target
 * testee, conformance/testees/c-target). Checking needs no recursion, so
 * hostile nesting cannot exhaust the stack; nesting is still limited to
 * JV_MAX_DEPTH.
 *
 * A jv_t is valid as long as the text it was parsed from.
 */
#ifndef JSONREAD_H
#define JSONREAD_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef enum { JV_NULL, JV_BOOL, JV_NUMBER, JV_STRING, JV_ARRAY, JV_OBJECT } jv_kind_t;

typedef struct {
    jv_kind_t kind;
    const char *p; /* the value's text, p[0 .. n) */
    size_t n;
} jv_t;

/* An iterator over an array's items or a string's bytes (UTF-8, escapes resolved). */
typedef struct {
    const char *p;
    const char *end;
    unsigned char pending[4]; /* the rest of a \u escape's UTF-8 bytes */
    unsigned npending;
} jv_iter_t;

#define JV_MAX_DEPTH 200

/* Check that text[0..len) is one JSON value (Python's NaN and Infinity
 * allowed); false on a syntax error, described in err (if not NULL). */
bool jv_parse(const char *text, size_t len, jv_t *out, char *err, size_t errcap);

/* The value of key in an object (the last one when repeated); false if absent or obj is not an object. */
bool jv_get(const jv_t *obj, const char *key, jv_t *out);

/* A number: whether it is written without fraction or exponent, and then
 * its value (saturated, with *overflow set, outside int64_t). */
bool jv_integer(const jv_t *v, int64_t *i, bool *overflow);
/* NaN and the infinities are numbers, but never integers. */

/* Arrays: jv_items, then jv_next_item until it returns false. */
void jv_items(const jv_t *arr, jv_iter_t *it);
bool jv_next_item(jv_iter_t *it, jv_t *item);

/* Strings: jv_chars, then jv_next_byte until it returns false. */
void jv_chars(const jv_t *str, jv_iter_t *it);
bool jv_next_byte(jv_iter_t *it, unsigned char *byte);
/* The string's bytes equal the NUL-terminated text. */
bool jv_string_is(const jv_t *str, const char *text);
/* The string's bytes into out (NUL-terminated); false if they do not fit in cap - 1 bytes or hold a NUL. */
bool jv_string_copy(const jv_t *str, char *out, size_t cap);

#endif
