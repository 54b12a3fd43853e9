/* crc32.h: the CRC-32 of ISO 3309 / zlib, written out independently of the
 * library's, for tests that corrupt a checkpoint's payload on purpose and
 * repair its checksum so that the loader's later checks are reached. */
#ifndef DEMILL_TEST_CRC32_H
#define DEMILL_TEST_CRC32_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

static inline uint32_t dm_test_crc32(const unsigned char *p, size_t n)
{
    uint32_t byte[256]; /* the CRC of each byte value, bit by bit */
    for (uint32_t v = 0; v < 256; v++) {
        uint32_t c = v;
        for (int b = 0; b < 8; b++)
            c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
        byte[v] = c;
    }
    uint32_t c = 0xFFFFFFFFu;
    for (size_t k = 0; k < n; k++)
        c = byte[(c ^ p[k]) & 0xFFu] ^ (c >> 8);
    return ~c;
}

/* A checkpoint's header is 32 bytes; its payload's CRC-32 is at offset 24. */
#define DM_TEST_CKPT_HEADER 32u

/* Rewrites the payload size and checksum of a checkpoint of n bytes. */
static inline void dm_test_ckpt_repair(unsigned char *b, size_t n)
{
    const uint64_t payload = n - DM_TEST_CKPT_HEADER;
    const uint32_t crc = dm_test_crc32(b + DM_TEST_CKPT_HEADER, n - DM_TEST_CKPT_HEADER);
    memcpy(b + 16, &payload, 8);
    memcpy(b + 24, &crc, 4);
}

#endif
