/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_crc.h - the two frame checksums of the OPEN protocol, table-driven,
 * tables computed by the generator from rules.yaml (crc).
 *   crc16: width 16, poly 0x8005, init 0x3aa3 (register), reflect_in true, reflect_out true, xorout 0x0
 *   crc32: width 32, poly 0x4c11db7, init 0x3aa3 (register), reflect_in true, reflect_out true, xorout 0x0
 * `init` is the register's start value in its own shift direction, as the
 * SDK holds it (ERRATA E21).
 */
#ifndef OSDK_CRC_H
#define OSDK_CRC_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* CRC over ASCII "123456789" (rules.yaml crc.*.check). */
#define OSDK_CRC16_CHECK 0x2752u
#define OSDK_CRC32_CHECK 0xe4d9dc14u

/* data holds len bytes (data may be NULL when len is 0). The comments
 * that open with an @ are ACSL contracts: what `make prove` proves the
 * functions against (docs/VERIFICATION.md). */
/*@ requires len == 0 || \valid_read(data + (0 .. len - 1));
    assigns \nothing; */
uint16_t osdk_crc16(const uint8_t *data, size_t len);
/*@ requires len == 0 || \valid_read(data + (0 .. len - 1));
    assigns \nothing; */
uint32_t osdk_crc32(const uint8_t *data, size_t len);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_CRC_H */
