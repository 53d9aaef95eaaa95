/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_columns.h - a decoded broadcast (osdk_decoder.h) as one row of typed
 * columns: the layout of each profile flattened to its leaves, named by their
 * dotted path in the value model ("quaternion.q0", "gimbal.limit.yaw_limit"),
 * each with the item it belongs to and the element type of its column. Floats
 * are kept as their IEEE bits (uint32/uint64), so a column holds every bit the
 * wire carried, NaN payloads and -0.0 included. The native module
 * (osdk_conformance/reference/_accel.c) fills the columns of `api.table` and
 * of the typed flight data with it; no Python object is made per value.
 */
#ifndef OSDK_COLUMNS_H
#define OSDK_COLUMNS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "osdk_decoder.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Element types of a column; F32 and F64 hold IEEE bits. */
typedef enum {
    OSDK_COL_BOOL = 0,
    OSDK_COL_U8, OSDK_COL_U16, OSDK_COL_U32, OSDK_COL_U64,
    OSDK_COL_I8, OSDK_COL_I16, OSDK_COL_I32, OSDK_COL_I64,
    OSDK_COL_F32, OSDK_COL_F64,
    OSDK_COL_TYPE_COUNT
} osdk_col_type_t;

/* Bytes per element of each type, in the order of osdk_col_type_t. */
extern const uint8_t osdk_col_size[OSDK_COL_TYPE_COUNT];

typedef struct {
    const char *name;      /* the leaf's dotted path */
    uint8_t item;          /* index into the set's items */
    uint8_t type;          /* osdk_col_type_t */
    const char *enum_name; /* the spec's enum ("osdk_broadcast_items.control_device"), or NULL */
} osdk_column_t;

typedef struct {
    const osdk_column_t *columns;
    size_t count;
    const char *const *items; /* the broadcast items, in wire order */
    size_t item_count;
} osdk_column_set_t;

/* The columns of the broadcast of `profile` (a value of osdk_payload.profile), NULL for none. */
const osdk_column_set_t *osdk_broadcast_columns(uint8_t profile);

/* Writes a decoded broadcast as row `row` of the columns of its profile: cols[i] is
 * column i's array of its element type, valid[i] its presence bytes (1 present, 0
 * absent; an absent value is written as 0). False when `b` holds no layout. */
bool osdk_broadcast_row(const osdk_payload_broadcast_t *b, void *const *cols, uint8_t *const *valid, size_t row);


#ifdef __cplusplus
}
#endif

#endif /* OSDK_COLUMNS_H */
