/* The C library of samples/checksums, built by scoopc (checksums.ecf names checksum.c). */
#include <stdint.h>

void checksum_fill(uint8_t *block, int32_t count, uint32_t seed);
uint32_t checksum_crc32(const uint8_t *block, int32_t count);
