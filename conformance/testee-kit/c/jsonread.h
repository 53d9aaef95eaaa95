/*
 * jsonread.h - a small JSON reader for the testee's request lines.
 *
 * Parses one JSON text into a tree allocated on the heap (requests only;
 * the generated decoder never allocates). Nesting is limited so hostile
 * input cannot exhaust the stack.
 */
#ifndef JSONREAD_H
#define JSONREAD_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef enum { JV_NULL, JV_BOOL, JV_NUMBER, JV_STRING, JV_ARRAY, JV_OBJECT } jv_kind_t;

typedef struct jv {
    jv_kind_t kind;
    bool boolean;
    bool is_int;        /* a number written without fraction or exponent */
    bool int_overflow;  /* is_int, but outside int64_t (i saturated) */
    int64_t i;
    double d;
    char *str;          /* JV_STRING: UTF-8, NUL-terminated (may hold NULs: see len) */
    size_t len;
    struct jv *items;   /* JV_ARRAY / JV_OBJECT values */
    char **keys;        /* JV_OBJECT keys */
    size_t count;
} jv_t;

#define JV_MAX_DEPTH 200

/* Parse text[0..len); NULL on a syntax error (message in err, if not NULL). */
jv_t *jv_parse(const char *text, size_t len, char *err, size_t errcap);
void jv_free(jv_t *v);
/* The value of key in an object (the last one when repeated), or NULL. */
const jv_t *jv_get(const jv_t *obj, const char *key);

#endif
