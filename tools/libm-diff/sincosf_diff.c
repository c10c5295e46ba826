/* glibc's sinf, cosf and sincosf against musl's (the C library of the web build), bit for bit,
   for every float with |x| <= LIMIT (default 1000), in one process: musl's own objects, taken
   from Debian's musl libc.a with their symbols renamed musl_* (see run). Prints how many inputs
   differ, by range, which of the two is correctly rounded there (reference: long double
   sinl/cosl rounded to float), and the first few. Usage: sincosf_diff [limit_bits_hex] */
#define _GNU_SOURCE
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

float musl_sinf(float);
float musl_cosf(float);
void musl_sincosf(float, float*, float*);

enum { SIN, COS, SINCOS_SIN, SINCOS_COS, NF };
static const char* names[NF] = {"sinf", "cosf", "sincosf (sin)", "sincosf (cos)"};
enum { NB = 5 };
static const double bounds[NB] = {0.78539816339744831, 3.1415926535897931, 100, 1000, INFINITY};
static uint32_t limit = 0x447a0000u; /* 1000.0f */

struct Stats {
  uint64_t count, differ[NF][NB], glibc_right[NF], musl_right[NF], neither[NF], self[2];
  float example[NF][6];
  int examples[NF];
};
static struct Stats stats[2];

static int same(float a, float b) {
  uint32_t ua, ub;
  memcpy(&ua, &a, 4);
  memcpy(&ub, &b, 4);
  return (a != a && b != b) || ua == ub;
}

static void eval(float x, float g[NF], float m[NF]) {
  g[SIN] = sinf(x);
  g[COS] = cosf(x);
  sincosf(x, &g[SINCOS_SIN], &g[SINCOS_COS]);
  m[SIN] = musl_sinf(x);
  m[COS] = musl_cosf(x);
  musl_sincosf(x, &m[SINCOS_SIN], &m[SINCOS_COS]);
}

static void* work(void* arg) {
  struct Stats* s = &stats[(intptr_t)arg];
  for (uint64_t v = (uint64_t)(intptr_t)arg; v <= 2 * (uint64_t)limit + 1; v += 2) {
    uint32_t u = (uint32_t)(v >> 1) | (uint32_t)(v & 1) << 31; /* +x and -x */
    float x, g[NF], m[NF];
    memcpy(&x, &u, 4);
    ++s->count;
    eval(x, g, m);
    s->self[0] += !same(g[SIN], g[SINCOS_SIN]) || !same(g[COS], g[SINCOS_COS]);
    s->self[1] += !same(m[SIN], m[SINCOS_SIN]) || !same(m[COS], m[SINCOS_COS]);
    for (int f = 0; f < NF; ++f) {
      if (same(g[f], m[f])) continue;
      int b = 0;
      while (fabs(x) > bounds[b]) ++b;
      ++s->differ[f][b];
      float exact = (float)(f == SIN || f == SINCOS_SIN ? sinl(x) : cosl(x));
      if (same(exact, g[f])) ++s->glibc_right[f];
      else if (same(exact, m[f])) ++s->musl_right[f];
      else ++s->neither[f];
      if (s->examples[f] < 6) s->example[f][s->examples[f]++] = x;
    }
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc > 1) limit = (uint32_t)strtoul(argv[1], 0, 16);
  pthread_t threads[2];
  for (intptr_t t = 0; t < 2; ++t) pthread_create(&threads[t], 0, work, (void*)t);
  for (int t = 0; t < 2; ++t) pthread_join(threads[t], 0);
  float lim;
  memcpy(&lim, &limit, 4);
  printf("%llu floats, |x| <= %g; results compared bit for bit (any NaN equals any NaN)\n",
         (unsigned long long)(stats[0].count + stats[1].count), lim);
  printf("sinf/cosf and sincosf disagree: within glibc %llu times, within musl %llu times\n",
         (unsigned long long)(stats[0].self[0] + stats[1].self[0]), (unsigned long long)(stats[0].self[1] + stats[1].self[1]));
  for (int f = 0; f < NF; ++f) {
    uint64_t total = 0;
    printf("%s: glibc and musl differ for", names[f]);
    for (int b = 0; b < NB; ++b) {
      uint64_t n = stats[0].differ[f][b] + stats[1].differ[f][b];
      total += n;
      printf(" %llu (|x| <= %g)%s", (unsigned long long)n, bounds[b], b + 1 < NB ? "," : "");
    }
    printf(" = %llu floats; correctly rounded there: glibc %llu, musl %llu, neither %llu\n", (unsigned long long)total,
           (unsigned long long)(stats[0].glibc_right[f] + stats[1].glibc_right[f]),
           (unsigned long long)(stats[0].musl_right[f] + stats[1].musl_right[f]),
           (unsigned long long)(stats[0].neither[f] + stats[1].neither[f]));
    for (int t = 0; t < 2; ++t)
      for (int i = 0; i < stats[t].examples[f]; ++i) {
        float x = stats[t].example[f][i], g[NF], m[NF];
        eval(x, g, m);
        printf("  x = %a: glibc %a, musl %a, exact %.12Lg\n", x, g[f], m[f],
               f == SIN || f == SINCOS_SIN ? sinl(x) : cosl(x));
      }
  }
  return 0;
}
