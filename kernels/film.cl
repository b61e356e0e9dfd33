/* film.cl: what a render kernel writes for its pixel, the same for every
 * integrator: the radiance of each sample (a bad one, NaN or infinite from a
 * degenerate hit, counts as black rather than blackening the pixel), the
 * first surface the camera ray met for the AOVs, and the pass's counters. */

/* What the camera ray found first, for the AOVs (texture_first_hit fills it). */
typedef struct {
	float3 albedo, normal;
	float depth;
	int object;    /* -1: nothing */
} first_hit;

static inline float3 film_finite(float3 l)
{
	return isfinite(l.x) && isfinite(l.y) && isfinite(l.z) ? l : (float3)(0.0f);
}

/* The aov buffer's sums (shared.h, AOV_FLOAT4S): albedo, normal and depth of
 * the samples that hit, and the object of the pixel's sample 0. */
static inline void film_add_aov(global float4 *aov, int pixel, const first_hit *f, int sample)
{
	global float4 *a = aov + AOV_FLOAT4S * pixel;
	if (f->object >= 0) {
		a[0] += (float4)(f->albedo, 1.0f);
		a[1] += (float4)(f->normal, 0.0f);
		a[2].x += f->depth;
	}
	if (sample == 0)
		a[2].y = (float)f->object;
}

/* The film holds each pixel's sums in fixed point (shared.h's
 * FILM_FRACTION_BITS; tests as plain counts): integers add in any order to the
 * same total, so a render split into sample ranges, regions, passes or devices merges into
 * exactly the sums of one run. A sample's radiance is held within
 * +-FILM_SAMPLE_MAX, so 2^15 samples of it still fit in 63 bits. */
#define FILM_SAMPLE_MAX 1048576.0f

static inline long4 film_fixed(float3 l, uint tests)
{
	float3 c = clamp(l, -FILM_SAMPLE_MAX, FILM_SAMPLE_MAX) * (float)(1 << FILM_FRACTION_BITS);
	return (long4)(convert_long3_rte(c), (long)tests);
}

/* The background's share of a sample (POV-Ray's transmittance, 1 - alpha),
 * summed where the aov buffer has room: a[2].z. */
static inline void film_add_transm(global float4 *aov, int pixel, float transm)
{
	aov[AOV_FLOAT4S * pixel + 2].z += clamp(transm, 0.0f, 1.0f);
}

/* The work item's ray and test counters into the pass's. */
static inline void film_add_counts(global uint *counters, const uint *counts)
{
	for (int i = 0; i < COUNT_N; i++)
		atomic_add(&counters[i], counts[i]);
}
