/* splitmix64 (Steele, Lea and Flood 2014): a tiny, seedable stream of
 * uniform numbers for the studies' random test points and resamples, where a
 * counter-based sequence (core/sampling/sobol.h) is not what is wanted. The state
 * advances by the golden-ratio increment; the output is its 64-bit mix. */
#ifndef GTLAB_CORE_SAMPLING_SPLITMIX64_H
#define GTLAB_CORE_SAMPLING_SPLITMIX64_H

/* The next number of the stream, uniform in [0, 1) with 53 bits. */
static inline double splitmix64_uniform01(unsigned long long *state)
{
    unsigned long long z = (*state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

#endif
