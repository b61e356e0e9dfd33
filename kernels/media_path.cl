/* media_path.cl: participating media in the path tracer, without bias.
 *
 * Along each segment of a path the media it is in (media_list_at) are crossed
 * by delta tracking against one majorant for all channels (media_majorant):
 * tentative collisions at exponential distances; at each, the emission adds
 * beta * emission / majorant (a track-length estimate of the integral of the
 * emission times the transmittance), and one event is chosen with the
 * probabilities of the channels' mean absorption, scattering and null
 * coefficients, beta weighted by each channel's coefficient over the
 * probability, so that chromatic media stay unbiased (an absorbing event
 * ends the path). Constant densities are the same walk with exact
 * coefficients. A scattering event is a vertex: next-event estimation toward
 * every light_source (light through transparent surfaces and media by ratio
 * tracking) and one emissive primitive (weighted by the power heuristic
 * against phase sampling), then a new direction from the phase function.
 *
 * Phase functions are POV-Ray's shapes normalized to integrate to 1 over the
 * sphere (POV-Ray's isotropic is 1, the path tracer's 1 / 4 pi, so a
 * light_source scatters a quarter of what POV-Ray scatters from the same
 * coefficient); several media at a point mix them by their scattering, per
 * channel. */

#define MEDIA_INV_4PI 0.0795774715f

/* One media's normalized phase function; cos_a: the direction sampled or to
 * the light against the ray's direction (1: straight on). */
static inline float media_phase_one(global const dev_media *md, float cos_a)
{
	float g = md->absorption.w, u;
	switch (md->type) {
	case MEDIA_RAYLEIGH: return 3.0f / (16.0f * M_PI_F) * (1.0f + cos_a * cos_a);
	case MEDIA_MIE_HAZY:
		u = 0.5f * (1.0f + cos_a);
		return (1.0f + 9.0f * pown(u, 8)) * (MEDIA_INV_4PI / 2.0f);
	case MEDIA_MIE_MURKY:
		u = 0.5f * (1.0f + cos_a);
		return (1.0f + 50.0f * pown(u, 32)) * (MEDIA_INV_4PI * 33.0f / 83.0f);
	case MEDIA_HG: return MEDIA_INV_4PI * (1.0f - g * g) / pow(fmax(1.0f + g * g - 2.0f * g * cos_a, 1e-8f), 1.5f);
	default: return MEDIA_INV_4PI;
	}
}

/* How one media samples its directions: Henyey-Greenstein exactly, the
 * others uniformly over the sphere. */
static inline float media_phase_pdf_one(global const dev_media *md, float cos_a)
{
	return md->type == MEDIA_HG ? media_phase_one(md, cos_a) : MEDIA_INV_4PI;
}

/* What the media at x scatter toward -d from direction wi, per channel
 * (sum of sigma_s * phase), and the pdf of sampling wi by media_phase_sample. */
static inline float3 media_scatter_eval(const scene_data *sc, const media_list *l, float3 x, float3 d, float3 wi, float *pdf)
{
	float3 f = (float3)(0.0f);
	float wsum = 0.0f, p = 0.0f, c = dot(wi, d);
	for (int i = 0; i < l->n; i++) {
		global const dev_media *md = &sc->media[l->m[i]];
		float3 ss = media_density(sc, md, x) * md->scattering.xyz;
		float w = (ss.x + ss.y + ss.z) / 3.0f;
		f += ss * media_phase_one(md, c);
		p += w * media_phase_pdf_one(md, c);
		wsum += w;
	}
	*pdf = wsum > 0.0f ? p / wsum : 0.0f;
	return f;
}

/* A direction from the mixture of the media's phase functions at x: a media
 * chosen by its mean scattering, then its phase (u.x chooses, u.yz the direction). */
static inline float3 media_phase_sample(const scene_data *sc, const media_list *l, float3 x, float3 d, float3 u)
{
	float wsum = 0.0f, w[MEDIA_LIST];
	for (int i = 0; i < l->n; i++) {
		global const dev_media *md = &sc->media[l->m[i]];
		float3 ss = media_density(sc, md, x) * md->scattering.xyz;
		w[i] = (ss.x + ss.y + ss.z) / 3.0f;
		wsum += w[i];
	}
	int k = 0;
	float acc = 0.0f;
	for (; k < l->n - 1; k++) {
		acc += w[k];
		if (u.x * wsum < acc)
			break;
	}
	global const dev_media *md = &sc->media[l->m[k]];
	float g = md->type == MEDIA_HG ? md->absorption.w : 0.0f;
	float cos_t;
	if (fabs(g) < 1e-3f) {
		cos_t = 1.0f - 2.0f * u.y;
	} else {   /* the inverse of HG's cdf, in the ray's direction */
		float q = (1.0f - g * g) / (1.0f - g + 2.0f * g * u.y);
		cos_t = clamp((1.0f + g * g - q * q) / (2.0f * g), -1.0f, 1.0f);
	}
	float sin_t = sqrt(fmax(0.0f, 1.0f - cos_t * cos_t));
	float3 t, b;
	intersect_basis(d, &t, &b);
	return normalize(sin_t * cospi(2.0f * u.z) * t + sin_t * sinpi(2.0f * u.z) * b + cos_t * d);
}

/* What a path's walk through media did on one segment. */
typedef struct {
	float t;           /* where it stopped: the scattering event's distance, or the segment's end */
	int event;         /* 0: reached the end, 1: scattered at t, 2: absorbed */
} media_walk;

/* Delta tracking over (o, o + tmax d) through l: adds what the media emit to
 * *radiance, weighs *beta, and says where the path goes on. */
static inline media_walk media_track(const scene_data *sc, const media_list *l, float3 o, float3 d, float tmax, float3 *beta,
                              float3 *radiance, uint key, uint dim)
{
	media_walk w = { tmax, 0 };
	float maj = media_majorant(sc, l);
	if (l->n == 0 || !(maj > 0.0f))
		return w;
	uint state = rng_hash(key ^ rng_hash(dim + 0x3c6ef372U));
	float x = 0.0f;
	for (int k = 0; k < MEDIA_STEPS; k++) {
		x -= log(1.0f - media_next(&state)) / maj;
		if (!(x < tmax))
			return w;
		float3 p = o + x * d;
		float3 sa = (float3)(0.0f), ss = (float3)(0.0f), em = (float3)(0.0f);
		for (int i = 0; i < l->n; i++) {
			global const dev_media *md = &sc->media[l->m[i]];
			float3 rho = media_density(sc, md, p);
			sa += rho * md->absorption.xyz;
			ss += rho * md->scattering.xyz;
			em += rho * md->emission.xyz;
		}
		*radiance += *beta * em / maj;
		float3 sn = fmax((float3)(maj) - sa - ss, 0.0f);
		float pa = (sa.x + sa.y + sa.z) / (3.0f * maj), ps = (ss.x + ss.y + ss.z) / (3.0f * maj);
		float pn = (sn.x + sn.y + sn.z) / (3.0f * maj);
		float u = media_next(&state) * (pa + ps + pn);
		if (u < pa) {
			w.t = x;
			w.event = 2;
			return w;
		}
		if (u < pa + ps) {   /* the phase and sigma_s come at the vertex (media_scatter_eval) */
			*beta /= maj * ps;
			w.t = x;
			w.event = 1;
			return w;
		}
		*beta *= sn / (maj * pn);
		if (!(pn > 0.0f))
			break;
	}
	w.event = 2;   /* the walk did not end: no light, rather than a wrong one */
	return w;
}

/* Next-event estimation at a scattering vertex x (beta already divided by
 * the event's probability): every light_source, and one emissive primitive
 * weighted against phase sampling. */
static inline float3 media_vertex_lights(const scene_data *sc, const media_list *l, media_stack ms, int solids, float3 x,
                                  float3 d, uint key, uint dim)
{
	float3 sum = (float3)(0.0f);
	for (int i = 0; i < sc->p->n_lights; i++) {
		global const dev_light *lt = &sc->lights[i];
		float3 pos = lt->position.xyz;
		if (lt->axis1.w > 0.0f) {
			float u = rng_uniform(key, dim + 2 * i), v = rng_uniform(key, dim + 2 * i + 1);
			float2 q = lt->axis2.w > 0.0f ? 0.5f * light_square_to_disc(u, v) : (float2)(u - 0.5f, v - 0.5f);
			pos += q.x * lt->axis1.xyz + q.y * lt->axis2.xyz;
		}
		float3 wi;
		float dist, k = 1.0f;
		if (lt->kind == LIGHT_KIND_PARALLEL) {
			wi = -lt->spot.xyz;
			dist = fmax(dot(pos - x, wi), 0.0f);
		} else {
			float3 to = pos - x;
			dist = length(to);
			if (dist <= 0.0f)
				continue;
			wi = to / dist;
			k = light_fade(lt, dist);
			if (lt->kind == LIGHT_KIND_SPOT)
				k *= light_spot(lt, -wi);
		}
		if (k <= 0.0f || lt->no_media_interaction)
			continue;
		float pdf;
		float3 f = media_scatter_eval(sc, l, x, d, wi, &pdf);
		/* a light_source lights a surface facing it with pi * its colour: its irradiance */
		float3 light = M_PI_F * k * lt->color.xyz;
		if (!lt->shadowless && dist > 0.0f)
			light = media_shadow_path(sc, ms, solids, x, wi, 0.0f, dist, light, key, dim + 32 + (uint)i) *
			        fog_shadow(sc, lt, x, wi, dist, solids);
		sum += f * light;
	}
	if (sc->p->integrator != INTEGRATOR_PATH || sc->p->n_emitters == 0)
		return sum;
	float3 wi, pos;
	global const dev_emitter *e = light_emitter_sample(sc, x, key, dim + 24, &wi, &pos);
	if (!e)
		return sum;
	float dist = length(pos - x);
	float pdf_light = light_pdf(sc, e, x, wi, dist), pdf_phase;
	float3 f = media_scatter_eval(sc, l, x, d, wi, &pdf_phase);
	if (pdf_light <= 0.0f || (f.x <= 0.0f && f.y <= 0.0f && f.z <= 0.0f))
		return sum;
	sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	/* as from surfaces, every surface blocks: paths through them find the emitter by sampling */
	global const dev_params *p = sc->p;
	if (traverse_any(sc, sc->nodes, sc->prims, p->n_prims, p->n_planes, x, wi, 0.0f, dist * (1.0f - 1e-4f), sc->counts))
		return sum;
	float3 tr = media_transmittance(sc, l, x, wi, dist, key, dim + 27);
	return sum + tr * light_emitted(sc, e->prim, pos, wi, dist) * f *
	             (light_power_heuristic(pdf_light, pdf_phase) / pdf_light);
}
