/* rng.cl: counter-based random numbers.
 *
 * Every number is a pure function of (pixel, sample, dimension, seed), with the
 * bounce folded into the dimension, so a render split into sample ranges or tiles
 * and merged gives exactly the image of one run (DESIGN.md, Determinism). */

/* A 32-bit integer hash with good avalanche (Chris Wellons' lowbias32). */
static inline uint rng_hash(uint x)
{
	x ^= x >> 16;
	x *= 0x7feb352dU;
	x ^= x >> 15;
	x *= 0x846ca68bU;
	x ^= x >> 16;
	return x;
}

/* The key of one sample of one pixel; rng_uniform draws its dimensions. */
static inline uint rng_key(uint pixel, uint sample, uint seed)
{
	return rng_hash(pixel ^ rng_hash(sample ^ rng_hash(seed + 0x9e3779b9U)));
}

/* A uniform float in [0, 1): 24 bits, so 1.0f itself never comes out. */
static inline float rng_uniform(uint key, uint dim)
{
	return (float)(rng_hash(key ^ rng_hash(dim + 0x85ebca6bU)) >> 8) * (1.0f / 16777216.0f);
}

/* Dimensions used per bounce; bounce b uses RNG_DIMS_PER_BOUNCE * b + 0, 1, ... */
#define RNG_DIMS_PER_BOUNCE 64
