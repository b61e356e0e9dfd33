/* media_whitted.cl: the Whitted integrator's media, sampled as POV-Ray 3.7.0's
 * MediaFunction::ComputeMedia samples them.
 *
 * The segment is cut into lit and unlit stretches (a spotlight lights its
 * cone's, the other lights all of it), which share the intervals by ratio
 * (one interval when nothing lights it and the density is constant); each
 * interval is sampled by method 3 (adaptive, as POV-Ray 3.7.0 does it:
 * samples / 2 + 1 sub-intervals, each end sampled and the middle refined while
 * neighbours differ by more than aa_threshold, down aa_level) or by methods 1
 * and 2 (samples stratified in each interval, then POV-Ray's extra samples
 * while the variance of their mean is high); a sample's colour is the emission plus, for every
 * light_source that lights it, the light reaching the point (shadowed, and
 * dimmed by the media on its way) times POV-Ray's phase function, averaged
 * over the media, times the scattering. */

#define MEDIA_LIGHTS 64       /* light_sources whose lit stretch of a ray is found; the others light all of it */
#define MEDIA_MAX_DISTANCE 1e7f   /* POV-Ray's MAX_DISTANCE */

/* Where along a segment each light_source lights the media (POV-Ray's
 * LightSourceEntry): a spotlight its cone, the others all of it. */
typedef struct {
	float s0[MEDIA_LIGHTS], s1[MEDIA_LIGHTS];
} media_spans;

/* The stretch (d1, d2) of the ray (o, d) in a spotlight's falloff cone:
 * POV-Ray's ComputeSpotLightInterval. */
static inline bool media_spot_interval(global const dev_light *lt, float3 o, float3 d, float *d1, float *d2)
{
	float cf = lt->cos_falloff;
	float m = 1.0f / (cf * cf);
	float3 v = o - lt->position.xyz;
	float k1 = dot(d, lt->spot.xyz), k2 = dot(v, lt->spot.xyz), len = length(v);
	bool in_cone = len > 1e-10f && k2 / len >= cf;
	if (k1 <= 0.0f && k2 < 0.0f)
		return false;
	float k3 = dot(v, d), k4 = dot(v, v);
	float a = 1.0f - k1 * k1 * m, b = k3 - k1 * k2 * m, c = k4 - k2 * k2 * m;
	if (a != 0.0f) {
		float disc = b * b - a * c;
		if (disc > 1e-10f) {
			disc = sqrt(disc);
			float t1 = (-b + disc) / a, t2 = (-b - disc) / a;
			if (t1 > t2) {
				float t = t1;
				t1 = t2;
				t2 = t;
			}
			float l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
			if (l1 <= 0.0f && l2 <= 0.0f)
				return false;
			if (l1 <= 0.0f) {
				if (in_cone) {
					t1 = 0.0f;
					t2 = t2 > 0.0f ? t2 : MEDIA_MAX_DISTANCE;
				} else {
					t1 = t2;
					t2 = MEDIA_MAX_DISTANCE;
				}
			} else if (l2 <= 0.0f) {
				if (in_cone) {
					t2 = t1;
					t1 = 0.0f;
				} else {
					t2 = MEDIA_MAX_DISTANCE;
				}
			}
			*d1 = t1;
			*d2 = t2;
			return true;
		}
		if (disc > -1e-10f) {
			*d1 = in_cone ? 0.0f : -b / a;
			*d2 = in_cone ? -b / a : MEDIA_MAX_DISTANCE;
			return true;
		}
		return false;
	}
	if (in_cone) {
		*d1 = 0.0f;
		*d2 = -c / b;
		return true;
	}
	return false;
}

/* Each light's lit stretch of (o, o + t d); an unlit light's is empty
 * (s0 > s1). Returns how many lights light some of it. */
static inline int media_light_spans(const scene_data *sc, float3 o, float3 d, float t, media_spans *sp)
{
	int n = 0;
	for (int i = 0; i < min(sc->p->n_lights, MEDIA_LIGHTS); i++) {
		global const dev_light *lt = &sc->lights[i];
		float t1 = 0.0f, t2 = t;
		bool in = !lt->no_media_interaction;
		if (in && lt->kind == LIGHT_KIND_SPOT)
			in = media_spot_interval(lt, o, d, &t1, &t2) && t1 < t && t2 > 0.001f;
		sp->s0[i] = in ? fmax(t1, 0.0f) : 1.0f;
		sp->s1[i] = in ? fmin(t2, t) : 0.0f;
		n += in;
	}
	return n + max(sc->p->n_lights - MEDIA_LIGHTS, 0);
}

/* The light of every light_source scattered toward -d at x, before the
 * coefficient: sum of phase * light reaching x (shadowed, through the media). */
static inline float3 media_lights(const scene_data *sc, const media_list *l, media_stack s, float3 x, float3 d,
                           const media_spans *spans, float at)
{
	float3 sum = (float3)(0.0f);
	for (int i = 0; i < sc->p->n_lights; i++) {
		global const dev_light *lt = &sc->lights[i];
		if (lt->no_media_interaction || (i < MEDIA_LIGHTS && !(at >= spans->s0[i] && at <= spans->s1[i])))
			continue;
		float3 to = lt->position.xyz - x, dir;
		float dist, k = 1.0f;
		if (lt->kind == LIGHT_KIND_PARALLEL) {
			dir = -lt->spot.xyz;
			dist = dot(to, dir);
		} else {
			dist = length(to);
			dir = dist > 0.0f ? to / dist : (float3)(0.0f, 1.0f, 0.0f);
			k = light_fade(lt, dist);
			if (lt->kind == LIGHT_KIND_SPOT)
				k *= light_spot(lt, -dir);
		}
		float3 c = k * lt->color.xyz;
		if (k <= 0.0f || !(dist > 0.0f))
			continue;
		if (!lt->shadowless)
			c = media_shadow(sc, s, x, dir, 1e-4f, dist - 1e-3f, c) *   /* POV-Ray's SHADOW_TOLERANCE */
			    media_atmosphere_shadow(sc, lt, x, dir, dist, 0);
		sum += media_phase(sc, l, dot(dir, d)) * c;
	}
	return sum;
}

/* One sample at distance t: its colour (emission and scattered light) times
 * the length ds it stands for, and its optical depth over ds. */
static inline float3 media_sample(const scene_data *sc, const media_list *l, media_stack s, float3 o, float3 d, float t,
                           float ds, const media_spans *lit, float3 *od)
{
	float3 x = o + t * d;
	media_coeffs c = media_coefficients(sc, l, x);
	*od = c.extinction * ds;
	float3 col = c.emission;
	if (lit && (c.scattering.x > 0.0f || c.scattering.y > 0.0f || c.scattering.z > 0.0f))
		col += c.scattering * media_lights(sc, l, s, x, d, lit, t);
	return col * ds;
}

/* A small generator for jitter, keyed by the ray: POV-Ray's jitter is random too. */
static inline float media_jitter(uint *state)
{
	*state = rng_hash(*state + 0x9e3779b9U);
	return (float)(*state >> 8) * (1.0f / 16777216.0f) - 0.5f;
}

typedef struct {
	float d1, d3;
	float3 c1, c3, od1, od3;
	float w;
	int depth;
} media_aa_node;

/* Method 3's refinement of one sub-interval (d1, d3) of [s0, s0 + ds], whose
 * ends are sampled: POV-Ray's ComputeOneMediaSampleRecursive, walked with a
 * stack; each node's share of the result is w. */
static inline float3 media_refine(const scene_data *sc, const media_list *l, media_stack s, float3 o, float3 d, float s0,
                           float ds, const media_spans *lit, global const dev_media *im, float thr, media_aa_node root,
                           float3 *od_out, uint *rnd)
{
	media_aa_node stack[MEDIA_AA_STACK];
	int n = 0;
	stack[n++] = root;
	float3 res = (float3)(0.0f), od = (float3)(0.0f);
	while (n > 0) {
		media_aa_node nd = stack[--n];
		float d2 = 0.5f * (nd.d1 + nd.d3);
		float j = im->sampling.x != 0.0f ? im->sampling.x * (nd.d3 - nd.d1) * media_jitter(rnd) : 0.0f;
		float3 od2;
		float3 c2 = media_sample(sc, l, s, o, d, s0 + (d2 + j) * ds, ds, lit, &od2);
		if (nd.depth <= 0 || n + 2 > MEDIA_AA_STACK) {
			res += nd.w * (nd.c1 + c2 + nd.c3) / 3.0f;
			od += nd.w * (nd.od1 + od2 + nd.od3) / 3.0f;
			continue;
		}
		float3 dl = fabs(nd.c1 - c2), dr = fabs(c2 - nd.c3);
		if (dl.x + dl.y + dl.z > thr) {
			media_aa_node c = { nd.d1, d2, nd.c1, c2, nd.od1, od2, 0.5f * nd.w, nd.depth - 1 };
			stack[n++] = c;
		} else {
			res += nd.w * (nd.c1 / 3.0f + c2 / 6.0f);
			od += nd.w * (nd.od1 / 3.0f + od2 / 6.0f);
		}
		if (dr.x + dr.y + dr.z > thr) {
			media_aa_node c = { d2, nd.d3, c2, nd.c3, od2, nd.od3, 0.5f * nd.w, nd.depth - 1 };
			stack[n++] = c;
		} else {
			res += nd.w * (c2 / 6.0f + nd.c3 / 3.0f);
			od += nd.w * (od2 / 6.0f + nd.od3 / 3.0f);
		}
	}
	*od_out = od;
	return res;
}

/* One interval [s0, s0 + ds] by method 3, as POV-Ray 3.7.0 samples it: its
 * emitted colour te and optical depth od, each a mean over its
 * min_samples / 2 + 1 (at least 2) sub-intervals of width 1 / (that + 1) from
 * the interval's start (3.7 leaves the last stretch unsampled: its images
 * show it), each sub-interval attenuated by those before it. */
static inline void media_interval3(const scene_data *sc, const media_list *l, media_stack s, float3 o, float3 d, float s0,
                            float ds, const media_spans *lit, global const dev_media *im, float thr, float3 *te,
                            float3 *od, uint *rnd)
{
	int sub = max(2, min(im->min_samples, 4096) / 2 + 1);
	float dd = 1.0f / (float)(sub + 1), n = 1.0f / (float)sub, jit = im->sampling.x;
	float3 od0, od1;
	float d0 = 0.0f;
	float3 c0 = media_sample(sc, l, s, o, d, s0 + ds * (jit != 0.0f ? dd * jit * media_jitter(rnd) : 0.0f), ds, lit,
	                         &od0);
	float3 sum_te = (float3)(0.0f), sum_od = (float3)(0.0f);
	for (int j = 1; j <= sub; j++) {
		d0 += dd;
		float3 c1 = media_sample(sc, l, s, o, d, s0 + ds * (d0 + (jit != 0.0f ? dd * jit * media_jitter(rnd) : 0.0f)),
		                         ds, lit, &od1);
		media_aa_node root = { d0 - dd, d0, c0, c1, od0, od1, 1.0f, min(im->aa_level, 16) - 1 };
		float3 odr;
		float3 r = media_refine(sc, l, s, o, d, s0, ds, lit, im, thr, root, &odr, rnd);
		sum_te += r * exp(-sum_od * n);
		sum_od += odr;
		c0 = c1;
		od0 = od1;
	}
	*te = sum_te * n;
	*od = sum_od * n;
}

/* POV-Ray's Sample_Threshold for k samples: the chi-square quantile at the
 * media's confidence for k degrees of freedom (exact for 1, Wilson and
 * Hilferty's approximation above, within 7% at 2 and closer after), scaled. */
static inline float media_threshold(global const dev_media *im, int k)
{
	if (k <= 1)
		return im->sampling.w * im->chi_1;
	float a = 2.0f / (9.0f * (float)k), c = 1.0f - a + im->chi_z * sqrt(a);
	return im->sampling.w * (float)k * fmax(c, 0.0f) * c * c;
}

/* One interval by methods 1 and 2: min_samples stratified samples (random
 * within their strata by jitter; method 1: anywhere in the interval), each
 * attenuated from the interval's start as POV-Ray's regular sampling does;
 * then, up to max_samples, more at random while the variance of their mean
 * in some channel is at its threshold or over (POV-Ray's confidence test). */
static inline void media_interval12(const scene_data *sc, const media_list *l, media_stack s, float3 o, float3 d, float s0,
                             float ds, const media_spans *lit, global const dev_media *im, float3 *te, float3 *od,
                             uint *rnd)
{
	int n = max(1, im->min_samples), k = 0;
	float3 sum_te = (float3)(0.0f), sum_te2 = (float3)(0.0f), sum_od = (float3)(0.0f);
	for (;;) {
		if (k >= n) {   /* the extra samples: ComputeMediaRegularSampling */
			if (im->max_samples <= n || k > im->max_samples)
				break;
			float inv = 1.0f / (float)k;
			float3 va = (sum_te2 * inv - (sum_te * inv) * (sum_te * inv)) * inv;
			float th = media_threshold(im, k);
			if (!(va.x >= th || va.y >= th || va.z >= th))
				break;
		}
		float u = im->method == 1 || k >= n ? media_jitter(rnd) + 0.5f
		                                    : ((float)k + 0.5f + im->sampling.x * (media_jitter(rnd) + 0.5f)) / (float)n;
		float3 o1;
		float3 c = media_sample(sc, l, s, o, d, s0 + u * ds, ds, lit, &o1);
		float3 e = c * exp(-o1 * u);
		sum_te += e;
		sum_te2 += e * e;
		sum_od += o1;
		k++;
	}
	*te = sum_te / (float)k;
	*od = sum_od / (float)k;
}

/* POV-Ray's ComputeMedia over (o, o + t d) for the media of l, on colour, the
 * light coming from the segment's end: colour * exp(-depth) + what the media
 * emit and scatter toward o. s: the interiors the ray is in (for light rays). */
static inline float3 media_whitted(const scene_data *sc, const media_list *l, media_stack s, float3 o, float3 d, float t,
                            float3 colour)
{
	if (l->n == 0 || !(t > 0.0f))
		return colour;
	t = fmin(t, MEDIA_HUGE);
	global const dev_media *im = &sc->media[l->m[0]];
	float thr = im->sampling.y;
	for (int i = 1; i < l->n; i++) {   /* the media with most intervals leads (the first of them) */
		global const dev_media *md = &sc->media[l->m[i]];
		if (md->intervals > im->intervals)
			im = md;
		thr = fmin(thr, md->sampling.y);
	}
	/* the lit and unlit stretches (ComputeMediaLightInterval): the lights'
	 * starts and ends sorted apart, overlapping stretches merged */
	media_spans spans;
	float a[MEDIA_LIGHTS], b[MEDIA_LIGHTS];
	int n_lit = media_light_spans(sc, o, d, t, &spans), n = 0;
	for (int i = 0; i < min(sc->p->n_lights, MEDIA_LIGHTS); i++) {
		if (spans.s0[i] > spans.s1[i])
			continue;
		int k = n++;
		for (; k > 0 && a[k - 1] > spans.s0[i]; k--)
			a[k] = a[k - 1];
		a[k] = spans.s0[i];
		k = n - 1;
		for (; k > 0 && b[k - 1] > spans.s1[i]; k--)
			b[k] = b[k - 1];
		b[k] = spans.s1[i];
	}
	if (n_lit > n) {   /* lights past MEDIA_LIGHTS light everything */
		a[0] = 0.0f;
		b[0] = t;
		n = 1;
	}
	float lo[2 * MEDIA_LIGHTS + 1], hi[2 * MEDIA_LIGHTS + 1];
	bool lit[2 * MEDIA_LIGHTS + 1];
	int m = 0;
	if (n == 0) {
		lo[0] = 0.0f, hi[0] = t, lit[0] = false;
		m = 1;
	} else {
		if (a[0] > 0.0f)
			lo[m] = 0.0f, hi[m] = a[0], lit[m++] = false;
		lo[m] = a[0], hi[m] = b[0], lit[m++] = true;
		for (int i = 1; i < n; i++) {
			if (a[i] > hi[m - 1]) {
				lo[m] = hi[m - 1], hi[m] = a[i], lit[m++] = false;
				lo[m] = a[i], hi[m] = b[i], lit[m++] = true;
			} else if (b[i] > hi[m - 1]) {
				hi[m - 1] = b[i];
			}
		}
		if (hi[m - 1] < t)
			lo[m] = hi[m - 1], hi[m] = t, lit[m++] = false;
	}
	/* how many intervals each stretch gets (ComputeMediaSampleInterval) */
	int intervals = max(min(im->intervals, MEDIA_INTERVALS_MAX), m);
	float ratio = im->sampling.z, sum = 0.0f;
	for (int i = 0; i < m; i++)
		sum += lit[i] ? ratio : 1.0f - ratio;
	uint rnd = as_uint(o.x) ^ rng_hash(as_uint(d.y) ^ rng_hash(as_uint(d.x) + as_uint(t)));
	float3 total_od = (float3)(0.0f), te_sum = (float3)(0.0f);
	int remaining = intervals;
	for (int i = 0; i < m; i++) {
		int k;
		if (m == 1) {
			k = !lit[0] && media_constant(sc, l) ? 1 : intervals;
		} else {
			k = (int)((lit[i] ? ratio : 1.0f - ratio) / sum * (float)intervals) + 1;
			k = min(k, remaining - m + i + 1);
		}
		k = max(k, 1);
		remaining -= k;
		float ds = (hi[i] - lo[i]) / (float)k;
		for (int j = 0; j < k; j++) {
			float3 te, od;
			const media_spans *ls = lit[i] ? &spans : 0;
			if (im->method == 3)
				media_interval3(sc, l, s, o, d, lo[i] + (float)j * ds, ds, ls, im, thr, &te, &od, &rnd);
			else
				media_interval12(sc, l, s, o, d, lo[i] + (float)j * ds, ds, ls, im, &te, &od, &rnd);
			te_sum += te * exp(-total_od);
			total_od += od;
		}
	}
	return colour * exp(-total_od) + te_sum;
}

