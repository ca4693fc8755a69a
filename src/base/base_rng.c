/* The seeded random stream: xoshiro256** (Blackman and Vigna), seeded through splitmix64.
 * Integer-only, so identical on every platform; real draws take the top bits. */
#include "amorph/base.h"

#include <string.h>

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static uint64_t splitmix64(uint64_t* x)
{
    uint64_t z = (*x += UINT64_C(0x9e3779b97f4a7c15));
    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

void am_rng_seed(am_rng* r, uint64_t seed)
{
    uint64_t x = seed;
    for (int i = 0; i < 4; i++) r->s[i] = splitmix64(&x);
    if (!(r->s[0] | r->s[1] | r->s[2] | r->s[3])) r->s[0] = 1;
}

uint64_t am_rng_u64(am_rng* r)
{
    uint64_t* s = r->s;
    uint64_t out = rotl(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return out;
}

uint32_t am_rng_below(am_rng* r, uint32_t n)
{
    if (n <= 1) return 0;
    /* rejection keeps it unbiased: accept only below the largest multiple of n */
    uint64_t limit = UINT64_MAX - (UINT64_MAX % n);
    uint64_t x;
    do x = am_rng_u64(r);
    while (x >= limit);
    return (uint32_t)(x % n);
}

am_real am_rng_unit(am_rng* r)
{
#if defined(AM_REAL_FIXED_POINT)
    return (am_real)(am_rng_u64(r) >> (64 - AM_FIX_FRAC)); /* the top bits are the fraction */
#elif defined(AM_REAL_DOUBLE)
    return (am_real)(am_rng_u64(r) >> 11) * AM_R(1.0 / 9007199254740992.0);
#else
    return (am_real)(uint32_t)(am_rng_u64(r) >> 40) * AM_R(1.0 / 16777216.0);
#endif
}

am_real am_rng_range(am_rng* r, am_real lo, am_real hi) { return lo + AM_MUL(hi - lo, am_rng_unit(r)); }

int am_rng_chance(am_rng* r, am_real p) { return am_rng_unit(r) < p; }

am_real am_rng_normal(am_rng* r)
{
    am_real u1 = AM_R(1) - am_rng_unit(r); /* (0, 1] */
    am_real u2 = am_rng_unit(r);
    return AM_MUL(am_sqrt(AM_MUL(AM_R(-2), am_log(u1))), am_cos(AM_MUL(AM_MUL(AM_R(2), AM_PI), u2)));
}

uint64_t am_hash_bytes(uint64_t h, const void* data, unsigned long n)
{
    const unsigned char* p = (const unsigned char*)data;
    for (unsigned long i = 0; i < n; i++) {
        h ^= p[i];
        h *= UINT64_C(0x100000001b3);
    }
    return h;
}

uint64_t am_hash_u64(uint64_t h, uint64_t v)
{
    unsigned char b[8];
    for (int i = 0; i < 8; i++) b[i] = (unsigned char)(v >> (8 * i)); /* byte order fixed */
    return am_hash_bytes(h, b, 8);
}

uint64_t am_hash_real(uint64_t h, am_real v)
{
    if (v == AM_R(0)) v = AM_R(0); /* -0 and +0 hash alike */
#if defined(AM_REAL_DOUBLE)
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    return am_hash_u64(h, bits);
#else
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    return am_hash_u64(h, bits);
#endif
}
