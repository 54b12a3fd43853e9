/* checkpoint.c: the fuzz target of the checkpoint loader.
 *
 * The first byte of an input chooses how the rest is used:
 *   even: as a whole checkpoint file, header and all (reaches the checks of
 *         the magic, version, byte order, size and checksum);
 *   odd:  as a payload, behind a correct header with its size and CRC-32
 *         (reaches the checks of every size, index and parameter, which a
 *         random checksum would almost never let through), of the format
 *         version in the byte's upper seven bits (1 when they are 0, as in
 *         the corpus's first inputs; 5, the sections of orientations and
 *         clumps, for 11).
 * Every load must return DEMILL_OK or DEMILL_ERR_FORMAT, never crash, leak or
 * touch memory it should not (run under AddressSanitizer and UBSan); a world
 * that loaded must survive a few steps and a save.
 *
 * Built two ways: with clang's libFuzzer (tests/fuzz/run, which explores)
 * and with a plain main() (replay.c), which CTest runs on the committed
 * corpus in tests/fuzz/corpus/ so that every input found once stays tested. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <demill.h>

#include "crc32.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static demill_world *w;
    if (!w && demill_world_create(3, &w) != DEMILL_OK)
        abort();
    if (size == 0)
        return 0;
    const bool payload = data[0] & 1;
    const size_t n = size - 1 + (payload ? DM_TEST_CKPT_HEADER : 0);
    unsigned char *b = malloc(n ? n : 1);
    if (!b)
        abort();
    if (payload) {
        static const unsigned char header[16] = {'D', 'E', 'M', 'I', 'L', 'L', 'C', 'K',
                                                 1, 0, 0, 0, 4, 3, 2, 1};
        memcpy(b, header, sizeof header);
        if (data[0] >> 1)
            b[8] = (unsigned char)(data[0] >> 1);
        memset(b + 28, 0, 4);
        memcpy(b + DM_TEST_CKPT_HEADER, data + 1, size - 1);
        dm_test_ckpt_repair(b, n);
    } else {
        memcpy(b, data + 1, size - 1);
    }
    const demill_status st = demill_world_load_buffer(w, b, n);
    if (st != DEMILL_OK && st != DEMILL_ERR_FORMAT) {
        fprintf(stderr, "load gave %d: %s\n", (int)st, demill_world_last_error(w));
        abort();
    }
    if (st == DEMILL_OK) {
        size_t bytes;
        demill_world_step(w, 3); /* any status but a crash */
        if (demill_world_save_buffer(w, NULL, 0, &bytes) != DEMILL_OK)
            abort();
    }
    free(b);
    return 0;
}
