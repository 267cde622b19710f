/* Pseudo-random bytes (a linear congruential generator) and CRC-32 (the polynomial of zlib). */
#include "checksum.h"

void checksum_fill(uint8_t *block, int32_t count, uint32_t seed) {
    uint32_t state = seed;
    for (int32_t i = 0; i < count; i++) {
        state = state * 1103515245u + 12345u;
        block[i] = (uint8_t) (state >> 16);
    }
}

uint32_t checksum_crc32(const uint8_t *block, int32_t count) {
    uint32_t crc = 0xFFFFFFFFu;
    for (int32_t i = 0; i < count; i++) {
        crc ^= block[i];
        for (int bit = 0; bit < 8; bit++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
}
