/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_tables.h - rule tables derived from spec/rules.yaml (through
 * tools/tables.py): the wire profiles, the classification and combination
 * of every control mode byte per profile, the setpoint ranges of every
 * documented combination, and the command names streams report.
 */
#ifndef OSDK_TABLES_H
#define OSDK_TABLES_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OSDK_PROFILE_COUNT 3
/* Profile ids (spec/rules.yaml), in value order: by profile index. */
extern const char *const osdk_profile_ids[OSDK_PROFILE_COUNT];
/* The value of the spec's profile enum (osdk_payload::profile) per profile index. */
extern const uint8_t osdk_profile_enum_values[OSDK_PROFILE_COUNT];
/* Profile index of a profile id, or -1. */
int osdk_profile_index(const char *id);

typedef enum {
    OSDK_MODE_DOCUMENTED = 0,
    OSDK_MODE_UNDOCUMENTED = 1,
    OSDK_MODE_LATER_FIRMWARE = 2,
    OSDK_MODE_INVALID = 3,
    OSDK_MODE_CLASS_COUNT_ = 4
} osdk_mode_class_t;
extern const char *const osdk_mode_class_names[4];

typedef enum {
    OSDK_AXIS_HORIZONTAL = 0,
    OSDK_AXIS_VERTICAL = 1,
    OSDK_AXIS_YAW = 2,
    OSDK_AXIS_COUNT_ = 3
} osdk_axis_t;
extern const char *const osdk_axis_names[3];

#define OSDK_MAX_COMBINATION 14

/* Classification (osdk_mode_class_t) and combination (-1: none) of each mode byte. */
extern const uint8_t osdk_mode_class[OSDK_PROFILE_COUNT][256];
extern const int8_t osdk_mode_combination[OSDK_PROFILE_COUNT][256];

/* An inclusive limit pair; a missing limit is unbounded. */
typedef struct {
    bool has_min;
    double min;
    bool has_max;
    double max;
} osdk_range_t;

/* Setpoint ranges by profile, combination and axis (all zero for
 * combinations a profile does not document). */
extern const osdk_range_t osdk_ranges[OSDK_PROFILE_COUNT][OSDK_MAX_COMBINATION + 1][3];

/* The command name streams report for (set, id): "unknown" when not listed. */
const char *osdk_command_name(unsigned cmd_set, unsigned cmd_id);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_TABLES_H */
