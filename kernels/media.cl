/* media.cl: participating media (POV-Ray 3.7's media { }), what both
 * integrators share (media_whitted.cl samples them as POV-Ray does,
 * media_path.cl without bias).
 *
 * A ray knows which interiors with media it is in (media_stack): it enters or
 * leaves one where it passes through a surface whose material has media, as
 * POV-Ray's interior list does (an interior met again is left). The media of
 * every interior on the stack act together at a point: their densities times
 * their coefficients add up (media_coefficients). Light rays through media
 * lose exp(-optical depth). */

#define MEDIA_NEST 4        /* interiors with media a ray can be inside at once */
#define MEDIA_LIST 8        /* media acting together at a point */
#define MEDIA_AA_STACK 24   /* method 3's refinements waiting */
#define MEDIA_HUGE 2e10f    /* how far a ray that leaves the scene goes through the atmosphere */
#define MEDIA_INTERVALS_MAX 64   /* intervals of one segment, at most */

typedef struct {
	int first[MEDIA_NEST], count[MEDIA_NEST];
	int n;
} media_stack;

static inline media_stack media_none(void)
{
	media_stack s;
	s.n = 0;
	return s;
}

/* Through a surface of material m: enters its interior's media, or leaves them. */
static inline media_stack media_cross(media_stack s, global const dev_material *m)
{
	if (m->n_media <= 0)
		return s;
	for (int i = 0; i < s.n; i++) {
		if (s.first[i] == m->media) {
			for (int k = i + 1; k < s.n; k++) {
				s.first[k - 1] = s.first[k];
				s.count[k - 1] = s.count[k];
			}
			s.n--;
			return s;
		}
	}
	if (s.n < MEDIA_NEST) {
		s.first[s.n] = m->media;
		s.count[s.n++] = m->n_media;
	}
	return s;
}

/* The media of every interior on the stack (or the atmosphere's), as indices. */
typedef struct {
	int m[MEDIA_LIST];
	int n;
} media_list;

static inline media_list media_gather(const media_stack *s)
{
	media_list l;
	l.n = 0;
	for (int i = 0; i < s->n; i++)
		for (int k = 0; k < s->count[i] && l.n < MEDIA_LIST; k++)
			l.m[l.n++] = s->first[i] + k;
	return l;
}

static inline media_list media_atmosphere(const scene_data *sc)
{
	media_list l;
	l.n = 0;
	for (int k = 0; k < sc->p->n_atmosphere && l.n < MEDIA_LIST; k++)
		l.m[l.n++] = sc->p->atmosphere + k;
	return l;
}

/* A media's density at x: the product of its densities' colours there. */
static inline float3 media_density(const scene_data *sc, global const dev_media *md, float3 x)
{
	float3 rho = md->density_rgb.xyz;
	for (int k = 0; k < MEDIA_DENSITIES && md->density[k] >= 0; k++) {
		shading_point sp;
		sp.x = sp.object_x = x;
		sp.uv = (float2)(0.0f);   /* a density has no surface */
		sp.ns = sp.ng = sp.n0 = (float3)(0.0f, 1.0f, 0.0f);
		sp.d = (float3)(0.0f, 0.0f, 1.0f);
		sp.m = &sc->materials[md->density[k]];
		rho *= texture_pigment(sc, &sp).rgb;
	}
	return fmax(rho, 0.0f);   /* a map's negative entries would make light out of nothing */
}

static inline bool media_constant(const scene_data *sc, const media_list *l)
{
	for (int i = 0; i < l->n; i++)
		if (sc->media[l->m[i]].density[0] >= 0)
			return false;
	return true;
}

typedef struct {
	float3 extinction, emission, scattering;
} media_coeffs;

static inline media_coeffs media_coefficients(const scene_data *sc, const media_list *l, float3 x)
{
	media_coeffs c = { (float3)(0.0f), (float3)(0.0f), (float3)(0.0f) };
	for (int i = 0; i < l->n; i++) {
		global const dev_media *md = &sc->media[l->m[i]];
		float3 rho = media_density(sc, md, x);
		c.extinction += rho * (md->absorption.xyz + md->scattering.w * md->scattering.xyz);
		c.emission += rho * md->emission.xyz;
		c.scattering += rho * md->scattering.xyz;
	}
	return c;
}

/* POV-Ray's phase functions, averaged over the media: cos_a is the cosine
 * between the direction to the light and the ray's direction (1: the light
 * comes from straight ahead). Isotropic is 1. */
static inline float media_phase(const scene_data *sc, const media_list *l, float cos_a)
{
	float k = 0.0f;
	for (int i = 0; i < l->n; i++) {
		global const dev_media *md = &sc->media[l->m[i]];
		float g = md->absorption.w;
		switch (md->type) {
		case MEDIA_RAYLEIGH: k += 0.799372013f * (1.0f + cos_a * cos_a); break;
		case MEDIA_MIE_HAZY: k += 0.576655375f * (1.0f + 9.0f * pown(0.5f * (1.0f + cos_a), 8)); break;
		case MEDIA_MIE_MURKY: k += 0.495714547f * (1.0f + 50.0f * pown(0.5f * (1.0f + cos_a), 32)); break;
		case MEDIA_HG: k += (1.0f - g * g) / pow(1.0f + g * g - 2.0f * g * cos_a, 1.5f); break;
		default: k += 1.0f; break;
		}
	}
	return l->n > 0 ? k / (float)l->n : 0.0f;
}

/* The optical depth of the media over (o, o + t d), as POV-Ray estimates it
 * for a light ray: exact for constant densities; else over the leading
 * media's intervals, each by its method with nothing emitted (method 3:
 * samples / 2 + 1 sub-intervals of 1 / (that + 1), each the mean of its ends
 * and middle, nothing emitted to refine; methods 1 and 2: stratified). */
static inline float3 media_optical_depth(const scene_data *sc, const media_list *l, float3 o, float3 d, float t)
{
	if (l->n == 0 || t <= 0.0f)
		return (float3)(0.0f);
	if (media_constant(sc, l))
		return t * media_coefficients(sc, l, o).extinction;
	global const dev_media *im = &sc->media[l->m[0]];
	for (int i = 1; i < l->n; i++)
		if (sc->media[l->m[i]].intervals > im->intervals)
			im = &sc->media[l->m[i]];
	int intervals = clamp(im->intervals, 1, MEDIA_INTERVALS_MAX);
	float ds = t / (float)intervals;
	float3 od = (float3)(0.0f);
	for (int i = 0; i < intervals; i++) {
		float s0 = (float)i * ds;
		float3 sum = (float3)(0.0f);
		if (im->method == 3) {
			int sub = max(2, min(im->min_samples, 4096) / 2 + 1);
			float dd = 1.0f / (float)(sub + 1);
			float3 e0 = media_coefficients(sc, l, o + s0 * d).extinction;
			for (int j = 1; j <= sub; j++) {
				float3 em = media_coefficients(sc, l, o + (s0 + ((float)j - 0.5f) * dd * ds) * d).extinction;
				float3 e1 = media_coefficients(sc, l, o + (s0 + (float)j * dd * ds) * d).extinction;
				sum += (e0 + em + e1) / 3.0f;
				e0 = e1;
			}
			od += sum * ds / (float)sub;
		} else {
			int n = clamp(im->min_samples, 1, 4096);
			for (int j = 0; j < n; j++)
				sum += media_coefficients(sc, l, o + (s0 + ((float)j + 0.5f) / (float)n * ds) * d).extinction;
			od += sum * ds / (float)n;
		}
	}
	return od;
}

/* What of colour, a light's, reaches o from along dir in (tmin, tmax) for a
 * ray inside the interiors of s: visibility_shadow's surfaces, and the media
 * of the hollow interiors it passes through (POV-Ray's ComputeShadowTexture). */
static inline float3 media_shadow(const scene_data *sc, media_stack s, float3 o, float3 dir, float tmin, float tmax,
                           float3 colour)
{
	sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	float start = 0.0f;
	for (int i = 0; i < VISIBILITY_CROSSINGS; i++) {
		traverse_hit h = visibility_closest(sc, o, dir, tmin, tmax - start, OBJECT_NO_SHADOW, RAY_SHADOW);
		if (h.prim < 0)   /* as POV-Ray, media count between surfaces only: an open container has none */
			return colour;
		media_list l = media_gather(&s);
		colour *= exp(-media_optical_depth(sc, &l, o, dir, h.t));
		shading_point sp = texture_point(sc, h, o, dir);
		float pass;
		float3 filter = texture_filter(sc, &sp, &pass);
		if (pass < sc->p->classic.w)
			return (float3)(0.0f);
		colour *= filter;
		if (!sp.entering)
			colour *= visibility_fade(sp.m, h.t);
		if (sc->objects[sp.object] & OBJECT_HOLLOW)
			s = media_cross(s, &sc->materials[sp.material]);
		o += h.t * dir;
		start += h.t;
		tmin = fmax(tmin, sp.eps);
		sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	}
	return (float3)(0.0f);
}

#define MEDIA_AROUND_CROSSINGS 64   /* surfaces a ray from the camera passes to find what holds it */

/* The interiors with media around x (the camera): those whose surfaces a ray
 * from x to infinity crosses an odd number of times. The host counts the solid
 * objects around the camera by their inside tests (lower_fog.c); media
 * containers are any closed surface, so the device counts crossings. */
static inline media_stack media_around(const scene_data *sc, float3 x)
{
	media_stack s = media_none();
	if (!(sc->p->scene_flags & SCENE_MEDIA))
		return s;
	float3 d = normalize((float3)(0.3141f, 0.8142f, 0.4873f));   /* along no axis, unlikely along a face */
	float tmin = 0.0f;
	for (int i = 0; i < MEDIA_AROUND_CROSSINGS; i++) {
		traverse_hit h = visibility_closest(sc, x, d, tmin, INFINITY, 0, RAY_SHADOW);
		if (h.prim < 0)
			break;
		shading_point sp = texture_point(sc, h, x, d);
		s = media_cross(s, &sc->materials[sp.material]);
		tmin = h.t + sp.eps;
	}
	return s;
}

/* What the atmosphere leaves of a light_source's light on its way to x
 * (dist along dir), in the Whitted integrator: POV-Ray dims shadow rays by the
 * atmosphere only toward a light with media_attenuation (and media_interaction),
 * outside solid objects, as it fogs them. */
static inline float3 media_atmosphere_shadow(const scene_data *sc, global const dev_light *l, float3 x, float3 dir, float dist,
                                      int solids)
{
	if (!l->media_attenuation || l->no_media_interaction || solids > 0 || sc->p->n_atmosphere == 0)
		return (float3)(1.0f);
	media_list a = media_atmosphere(sc);
	return exp(-media_optical_depth(sc, &a, x, dir, fmin(dist, MEDIA_HUGE)));
}

/* ---- what the path tracer shares with light.cl ---- */

/* The media acting on a path segment: its interiors' and the atmosphere's,
 * none inside a solid object (POV-Ray computes media for hollow rays only). */
static inline media_list media_list_at(const scene_data *sc, const media_stack *s, int solids)
{
	media_list l;
	l.n = 0;
	if (solids > 0 || !(sc->p->scene_flags & SCENE_MEDIA))
		return l;
	l = media_gather(s);
	for (int k = 0; k < sc->p->n_atmosphere && l.n < MEDIA_LIST; k++)
		l.m[l.n++] = sc->p->atmosphere + k;
	return l;
}

/* The path tracer's extinction is absorption + scattering: POV-Ray's
 * extinction factor would make or lose light. */
static inline float3 media_sigma_t(global const dev_media *md)
{
	return md->absorption.xyz + md->scattering.xyz;
}

/* A bound on the extinction of every channel along any ray through l. */
static inline float media_majorant(const scene_data *sc, const media_list *l)
{
	float m = 0.0f;
	for (int i = 0; i < l->n; i++) {
		global const dev_media *md = &sc->media[l->m[i]];
		float3 st = media_sigma_t(md);
		m += md->emission.w * fmax(st.x, fmax(st.y, st.z));
	}
	return m;
}

/* Uniform numbers after the dimension dim of a sample, as many as a walk
 * through media needs: a chain of hashes from rng_uniform's. */
static inline float media_next(uint *state)
{
	*state = rng_hash(*state ^ 0x68e31da4U);
	return (float)(*state >> 8) * (1.0f / 16777216.0f);
}

#define MEDIA_STEPS 4096   /* tentative collisions one estimate takes, at most */

/* The transmittance of l over (o, o + t d): exact for constant densities,
 * else ratio tracking against the majorant (unbiased; the product of
 * 1 - sigma_t / majorant at the tentative collisions). */
static inline float3 media_transmittance(const scene_data *sc, const media_list *l, float3 o, float3 d, float t, uint key,
                                  uint dim)
{
	if (l->n == 0 || !(t > 0.0f))
		return (float3)(1.0f);
	float3 st = (float3)(0.0f);
	if (media_constant(sc, l)) {
		for (int i = 0; i < l->n; i++)
			st += sc->media[l->m[i]].density_rgb.xyz * media_sigma_t(&sc->media[l->m[i]]);
		return exp(-st * fmin(t, MEDIA_HUGE));
	}
	float maj = media_majorant(sc, l);
	uint state = rng_hash(key ^ rng_hash(dim + 0x2545f491U));
	float3 tr = (float3)(1.0f);
	float x = 0.0f;
	for (int k = 0; k < MEDIA_STEPS && maj > 0.0f; k++) {
		x -= log(1.0f - media_next(&state)) / maj;
		if (x >= t)
			break;
		float3 s = (float3)(0.0f);
		for (int i = 0; i < l->n; i++) {
			global const dev_media *md = &sc->media[l->m[i]];
			s += media_density(sc, md, o + x * d) * media_sigma_t(md);
		}
		tr *= clamp((float3)(1.0f) - s / maj, 0.0f, 1.0f);
		if (tr.x <= 0.0f && tr.y <= 0.0f && tr.z <= 0.0f)
			break;
	}
	return tr;
}

/* What of colour, a light_source's, reaches x along dir in (tmin, tmax) for
 * the path tracer: visibility_shadow's surfaces, and the media of the hollow
 * interiors it passes through and the atmosphere's. */
static inline float3 media_shadow_path(const scene_data *sc, media_stack s, int solids, float3 o, float3 dir, float tmin,
                                float tmax, float3 colour, uint key, uint dim)
{
	if (!(sc->p->scene_flags & SCENE_MEDIA))
		return visibility_shadow(sc, o, dir, tmin, tmax, colour);
	sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	float start = 0.0f;
	for (int i = 0; i < VISIBILITY_CROSSINGS; i++) {
		traverse_hit h = visibility_closest(sc, o, dir, tmin, tmax - start, OBJECT_NO_SHADOW, RAY_SHADOW);
		media_list l = media_list_at(sc, &s, solids);
		colour *= media_transmittance(sc, &l, o, dir, h.prim < 0 ? tmax - start : h.t, key, dim + (uint)i);
		if (h.prim < 0)
			return colour;
		shading_point sp = texture_point(sc, h, o, dir);
		float pass;
		float3 filter = texture_filter(sc, &sp, &pass);
		if (pass < sc->p->classic.w)
			return (float3)(0.0f);
		colour *= filter;
		if (!sp.entering)
			colour *= visibility_fade(sp.m, h.t);
		if (sc->objects[sp.object] & OBJECT_HOLLOW)
			s = media_cross(s, &sc->materials[sp.material]);
		o += h.t * dir;
		start += h.t;
		tmin = fmax(tmin, sp.eps);
		sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	}
	return (float3)(0.0f);
}
