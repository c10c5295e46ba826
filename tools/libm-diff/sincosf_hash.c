/* sinf, cosf and sincosf of every float with |x| <= LIMIT (every STRIDE-th bit pattern), hashed
   (FNV-1a over the results' bits, a NaN counted as 0x7fc00000). Built against glibc (gcc), against
   musl (musl-gcc -static), and against musl's own objects renamed musl_* (-DRENAMED_MUSL): the
   last two must agree for the one-process diff (sincosf_diff.c) to speak for musl.
   -fno-builtin keeps each call as written. Usage: ./a.out [limit_bits_hex [stride]] */
#define _GNU_SOURCE
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef RENAMED_MUSL
float musl_sinf(float); float musl_cosf(float); void musl_sincosf(float, float*, float*);
#define sinf musl_sinf
#define cosf musl_cosf
#define sincosf musl_sincosf
#endif
static uint32_t canon(float r) { uint32_t u; memcpy(&u, &r, 4); return r != r ? 0x7fc00000u : u; }
static uint64_t fnv(uint64_t h, uint32_t v) { for (int i = 0; i < 32; i += 8) h = (h ^ ((v >> i) & 0xff)) * 0x100000001b3ull; return h; }
int main(int argc, char** argv) {
  uint32_t limit = argc > 1 ? (uint32_t)strtoul(argv[1], 0, 16) : 0x447a0000u;  /* 1000.0f */
  uint32_t stride = argc > 2 ? (uint32_t)strtoul(argv[2], 0, 10) : 1;
  uint64_t h[4] = {0xcbf29ce484222325ull, 0xcbf29ce484222325ull, 0xcbf29ce484222325ull, 0xcbf29ce484222325ull};
  uint64_t n = 0;
  for (uint64_t m = 0; m <= limit; m += stride)
    for (uint32_t sign = 0; sign < 2; ++sign) {
      uint32_t u = (uint32_t)m | sign << 31;
      float x, s, c;
      memcpy(&x, &u, 4);
      sincosf(x, &s, &c);
      h[0] = fnv(h[0], canon(sinf(x)));
      h[1] = fnv(h[1], canon(cosf(x)));
      h[2] = fnv(h[2], canon(s));
      h[3] = fnv(h[3], canon(c));
      ++n;
    }
  printf("%llu floats: sinf %016llx cosf %016llx sincosf.sin %016llx sincosf.cos %016llx\n", (unsigned long long)n,
         (unsigned long long)h[0], (unsigned long long)h[1], (unsigned long long)h[2], (unsigned long long)h[3]);
  return 0;
}
