/* fog.cl: POV-Ray 3.7's fog (Trace::ComputeFog), for both integrators.
 *
 * Along a segment of a ray that is in no solid object, each fog lets through
 * att = exp(-width * density / distance) of the light (never less than its
 * transmit), filtered by its colour as much as its filter says, and adds its
 * colour times 1 - att. Several fogs are each taken over the whole segment:
 * their transmittances multiply and their colours add, as POV-Ray adds them
 * (which is not the same as fogs one behind the other). A ray that leaves the
 * scene goes FOG_HUGE, POV-Ray's BOUND_HUGE. Shadow rays only lose light,
 * and only toward a light_source with media_attenuation (fog_shadow). */

#define FOG_HUGE 2e10f
#define FOG_NOISE_GENERATOR 2   /* POV-Ray's default; eclat has no global noise_generator */

/* What the fogs do to the light coming back along a segment: it becomes
 * add + att * light. */
typedef struct {
	float3 att, add;
} fog_effect;

/* Turbulence shrinks the distance through the fog, less so when the segment
 * is long (ComputeConstantFogColour, ComputeGroundFogColour); mid is the
 * segment's middle. */
static inline float fog_turbulence(global const dev_fog *f, float3 mid, float width)
{
	float k = exp(-width / f->distance);
	if (k == 0.0f)   /* the far, and the rays that leave the scene: no noise at 1e10 */
		return 1.0f;
	float t = pattern_turbulence(mid * f->turb.xyz, f->omega, f->lambda, f->octaves, FOG_NOISE_GENERATOR);
	return 1.0f - k * fmin(1.0f, t * f->turb.w);
}

/* The mean density of a ground fog between heights start and start + delta
 * (in fog_alt units above fog_offset): 1 below 0, 1 / (1 + h^2) above, whose
 * integral is atan(h). atan(a) - atan(b) is atan((a - b) / (1 + ab)) for
 * a, b > 0, which keeps nearly level rays from cancelling away their digits. */
static inline float fog_ground_density(float start, float delta)
{
	float end = start + delta;
	if (start <= 0.0f && end <= 0.0f)
		return 1.0f;
	if (start <= 0.0f)
		return (atan(end) - start) / delta;
	if (end <= 0.0f)
		return (atan(start) - end) / -delta;
	if (delta == 0.0f)
		return 1.0f / (start * start + 1.0f);
	return atan(-delta / (1.0f + start * end)) / -delta;
}

/* The transmittance of one fog over (o, o + width * d), d of unit length. */
static inline float fog_transmittance(global const dev_fog *f, float3 o, float3 d, float width)
{
	float density = 1.0f;
	if (f->type == FOG_GROUND) {
		float start = (dot(o, f->up.xyz) - f->offset) / f->alt;
		density = fog_ground_density(start, width * dot(d, f->up.xyz) / f->alt);
	}
	if (f->turb_on)
		width *= fog_turbulence(f, o + (0.5f * width) * d, width);
	return exp(-width * density / f->distance);
}

/* Every fog over a segment of length t (INFINITY: a ray that leaves the scene). */
static inline fog_effect fog_segment(const scene_data *sc, float3 o, float3 d, float t, bool shadow)
{
	fog_effect e = { (float3)(1.0f), (float3)(0.0f) };
	float width = fmin(t, FOG_HUGE);
	for (int i = 0; i < sc->p->n_fogs; i++) {
		global const dev_fog *f = &sc->fogs[i];
		float att = fmax(fog_transmittance(f, o, d, width), f->up.w);
		float3 rgb = f->colour.xyz;
		e.att *= att * ((1.0f - f->colour.w) + f->colour.w * rgb);
		if (!shadow)
			e.add += (1.0f - att) * rgb;
	}
	return e;
}

/* What is left of a light's colour after the fogs between x and the light,
 * dist along dir: POV-Ray fogs shadow rays only toward a light_source with
 * media_attenuation, and only outside solid objects (solids: those around x). */
static inline float3 fog_shadow(const scene_data *sc, global const dev_light *l, float3 x, float3 dir, float dist,
                         int solids)
{
	if (!l->media_attenuation || solids > 0 || sc->p->n_fogs == 0)
		return (float3)(1.0f);
	return fog_segment(sc, x, dir, dist, true).att;
}
