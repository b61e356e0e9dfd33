/* finish.cl: three of POV-Ray 3.7's finish and interior effects, read from
 * dev_material by both integrators: irid's thin-film tint, crand's grain and
 * an interior's fake caustics (eclat-scene(5) says where the path tracer
 * differs). */

/* irid's film thickness at x: POV-Ray's (Trace::ComputeIridColour), its
 * turbulence a fixed one (omega 0.5, lambda 2, 5 octaves) scaling the film by
 * 1 +/- turbulence. */
static inline float finish_irid_thickness(global const dev_material *m, float3 x)
{
	float t = m->irid.y;
	if (m->irid.z != 0.0f)
		t *= 1.0f + (2.0f * pattern_turbulence(x, 0.5f, 2.0f, 5, m->noise_generator) - 1.0f) * m->irid.z;
	return t;
}

/* What irid multiplies light by, coming from l and leaving toward the eye
 * along e (either way round: only the cosines' sizes count), about n: the
 * phase the film's two reflections differ by, per wavelength. */
static inline float3 finish_irid_tint(float amount, float thickness, float3 wl, float3 n, float3 l, float3 e)
{
	float phase = 2.0f * M_PI_F * thickness * (fabs(dot(n, l)) + fabs(dot(n, e)));
	return 1.0f + amount * (float3)(cos(phase / wl.x), cos(phase / wl.y), cos(phase / wl.z));
}

/* crand's uniform number for one light at a Whitted shading point: POV-Ray
 * draws one per light from a stream; the point's bits (a pure function of the
 * pixel) and the light stand for the stream's place, so a split render merges
 * to the same image. */
static inline float finish_crand_at(float3 x, int light, uint seed)
{
	uint k = rng_hash(as_uint(x.x) ^ rng_hash(as_uint(x.y) ^ rng_hash(as_uint(x.z) ^ rng_hash(seed ^ 0x63726e64U))));
	return rng_uniform(k, (uint)light);
}

/* An interior's fake caustics on a shadow ray along d through a surface of
 * normal n: POV-Ray's 1 + |n.d|^power, light gathered where it passes
 * straight through (Trace::ComputeShadowTexture). */
static inline float finish_caustics(global const dev_material *m, float3 n, float3 d)
{
	return 1.0f + pow(fabs(dot(n, d)), m->irid_wavelength.w);
}
