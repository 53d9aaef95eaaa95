/* CRC-16 and CRC-32 against the check values of rules.yaml (via the generated tables). */
#include <string.h>

#include "check.h"
#include "osdk_crc.h"

int main(void)
{
    static const unsigned char digits[] = "123456789";
    unsigned char frame[64];
    size_t n;
    CHECK_EQ(osdk_crc16(digits, 9), OSDK_CRC16_CHECK);
    CHECK_EQ(osdk_crc32(digits, 9), OSDK_CRC32_CHECK);
    CHECK_EQ(OSDK_CRC16_CHECK, 0x2752u);
    CHECK_EQ(OSDK_CRC32_CHECK, 0xE4D9DC14u);
    /* the worked movement control frame: CRC-16 0x72e1 over bytes 0-9, CRC-32 0xba01dbfc */
    n = unhex("aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba", frame);
    CHECK_EQ(n, 35);
    CHECK_EQ(osdk_crc16(frame, 10), 0x72e1u);
    CHECK_EQ(osdk_crc32(frame, n - 4), 0xba01dbfcu);
    /* residue: the CRC over data and its stored little-endian CRC is 0 */
    CHECK_EQ(osdk_crc32(frame, n), 0u);
    CHECK_EQ(osdk_crc16(frame, 12), 0u);
    /* empty input gives the initial register */
    CHECK_EQ(osdk_crc16(frame, 0), 0x3aa3u);
    return check_done("test_crc");
}
