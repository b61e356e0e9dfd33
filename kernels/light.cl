/* light.cl: next-event estimation.
 *
 * POV-Ray's light_sources are invisible: no ray can hit them, so every vertex
 * samples each of them. With no fade they do not fall off with distance: a light
 * of colour C gives a Lambertian surface of albedo a the radiance a * C * cos, the
 * radiance of that surface under irradiance pi * C * cos. An area_light spreads
 * the same total over its rectangle (or disc), as POV-Ray spreads it over its grid.
 *
 * Emissive surfaces are lights that rays can also hit: one is chosen by power,
 * a point on it sampled as its shape says (shape_emit_sample: by area, or by
 * solid angle for spheres seen from outside), and both strategies are weighted
 * by the power heuristic. Which shapes are sampled is PRIM_EMITTERS' list;
 * the others are found by rays alone. */

/* Concentric map of the square to the unit disc (Shirley and Chiu), for circular
 * area lights and the lens. */
static inline float2 light_square_to_disc(float u, float v)
{
	float a = 2.0f * u - 1.0f, b = 2.0f * v - 1.0f;
	if (a == 0.0f && b == 0.0f)
		return (float2)(0.0f);
	float r, phi;   /* the angle in units of pi (sinpi, cospi: material_sample_cosine) */
	if (fabs(a) > fabs(b)) {
		r = a;
		phi = 0.25f * (b / a);
	} else {
		r = b;
		phi = 0.5f - 0.25f * (a / b);
	}
	return r * (float2)(cospi(phi), sinpi(phi));
}

/* POV-Ray's fade: 2 / (1 + (d / fade_distance) ^ fade_power). */
static inline float light_fade(global const dev_light *l, float dist)
{
	float fd = l->position.w, fp = l->color.w;
	return fd > 0.0f && fp > 0.0f ? 2.0f / (1.0f + pow(dist / fd, fp)) : 1.0f;
}

/* POV-Ray's spotlight: full inside radius, a smooth step to zero at falloff,
 * sharpened by cos^tightness. */
static inline float light_spot(global const dev_light *l, float3 to_surface)
{
	float c = dot(to_surface, l->spot.xyz);
	if (c < l->cos_falloff)
		return 0.0f;
	float k = l->tightness > 0.0f ? pow(c, l->tightness) : 1.0f;
	if (c < l->spot.w) {
		float t = (c - l->cos_falloff) / (l->spot.w - l->cos_falloff);
		k *= t * t * (3.0f - 2.0f * t);
	}
	return k;
}

/* The sum over all light_sources of their contribution at x (normal n, facing
 * wo); solids: the solid objects around x, for fog_shadow. */
static inline float3 light_pov(const scene_data *sc, const bsdf *m, const material_lobes *lobes,
                        float3 x, float3 ng, float3 n, float3 wo, uint key, uint dim, int solids, media_stack ms)
{
	float3 sum = (float3)(0.0f);
	for (int i = 0; i < sc->p->n_lights; i++) {
		global const dev_light *l = &sc->lights[i];
		float3 pos = l->position.xyz;
		if (l->axis1.w > 0.0f) {
			float u = rng_uniform(key, dim + 2 * i), v = rng_uniform(key, dim + 2 * i + 1);
			float2 q = l->axis2.w > 0.0f ? 0.5f * light_square_to_disc(u, v) : (float2)(u - 0.5f, v - 0.5f);
			pos += q.x * l->axis1.xyz + q.y * l->axis2.xyz;
		}
		float3 wi;
		float dist, k = 1.0f;
		if (l->kind == LIGHT_KIND_PARALLEL) {
			wi = -l->spot.xyz;
			dist = fmax(dot(pos - x, wi), 0.0f);  /* only what lies before the light's plane shadows */
		} else {
			float3 to = pos - x;
			dist = length(to);
			if (dist <= 0.0f)
				continue;
			wi = to / dist;
			k = light_fade(l, dist);
			if (l->kind == LIGHT_KIND_SPOT)
				k *= light_spot(l, -wi);
		}
		float pdf;
		float3 f = material_eval(m, lobes, n, wo, wi, &pdf);
		if (k <= 0.0f || dot(ng, wi) <= 0.0f || (f.x <= 0.0f && f.y <= 0.0f && f.z <= 0.0f))
			continue;
		float3 light = k * l->color.xyz;
		if (!l->shadowless && dist > 0.0f)
			light = media_shadow_path(sc, ms, solids, x, wi, 0.0f, dist, light, key, dim + 2 * i) *
			        fog_shadow(sc, l, x, wi, dist, solids);
		sum += M_PI_F * light * f;
	}
	return sum;
}

/* The index of the emitter whose cdf interval holds u. */
static inline int light_choose(global const dev_emitter *em, int n, float u)
{
	int lo = 0, hi = n - 1;
	while (lo < hi) {
		int mid = (lo + hi) / 2;
		if (em[mid].cdf > u)
			hi = mid;
		else
			lo = mid + 1;
	}
	return lo;
}

/* The solid-angle pdf of sampling direction wi from x toward the emitter e,
 * met at distance t: what MIS needs for rays that hit emitters. */
static inline float light_pdf(const scene_data *sc, global const dev_emitter *e, float3 x, float3 wi, float t)
{
	return shape_emit_pdf(sc->prims, &sc->prims[e->prim], x, wi, t, e->pdf, e->area);
}

/* The radiance an emissive primitive sends from pos, reached along wi after
 * dist: its finish's emission times its pigment there. */
static inline float3 light_emitted(const scene_data *sc, int prim, float3 pos, float3 wi, float dist)
{
	global const dev_material *m = &sc->materials[sc->prims[prim].material];
	if (m->pattern < 0 && m->below < 0)
		return m->pigment.xyz * m->emission.xyz;
	traverse_hit h = { dist, prim, -1 };
	shading_point sp = texture_point(sc, h, pos - dist * wi, wi);
	return texture_emitted(sc, &sp);
}

static inline float light_power_heuristic(float a, float b)
{
	return a * a / (a * a + b * b);
}

/* A point pos on one emissive primitive chosen by power, seen from x along
 * wi, sampled as its shape does (shape_emit_sample), or NULL. Dimensions: dim
 * the choice, dim + 1 and dim + 2 the point. */
static inline global const dev_emitter *light_emitter_sample(const scene_data *sc, float3 x, uint key, uint dim, float3 *wi,
                                                      float3 *pos)
{
	global const dev_emitter *em = sc->emitters;
	global const dev_emitter *e = &em[light_choose(em, sc->p->n_emitters, rng_uniform(key, dim))];
	float u1 = rng_uniform(key, dim + 1), u2 = rng_uniform(key, dim + 2);
	return shape_emit_sample(sc->prims, &sc->prims[e->prim], x, u1, u2, wi, pos) ? e : 0;
}

/* One sample of one emissive primitive, weighted against BSDF sampling. */
static inline float3 light_emitters(const scene_data *sc, const bsdf *m, const material_lobes *lobes, float3 x,
                             float3 ng, float3 n, float3 wo, uint key, uint dim, media_stack ms, int solids)
{
	global const dev_params *p = sc->p;
	if (p->n_emitters == 0)
		return (float3)(0.0f);
	float3 wi, pos;
	global const dev_emitter *e = light_emitter_sample(sc, x, key, dim, &wi, &pos);
	if (!e)
		return (float3)(0.0f);
	float dist = length(pos - x);
	float pdf_light = light_pdf(sc, e, x, wi, dist), pdf_bsdf;
	float3 f = material_eval(m, lobes, n, wo, wi, &pdf_bsdf);
	if (pdf_light <= 0.0f || dot(ng, wi) <= 0.0f || (f.x <= 0.0f && f.y <= 0.0f && f.z <= 0.0f))
		return (float3)(0.0f);
	sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	/* stop short of the emitter itself; every surface blocks, since the paths
	 * that cross transparent ones find the emitter by BSDF sampling */
	if (traverse_any(sc, sc->nodes, sc->prims, p->n_prims, p->n_planes, x, wi, 0.0f, dist * (1.0f - 1e-4f), sc->counts))
		return (float3)(0.0f);
	media_list l = media_list_at(sc, &ms, solids);   /* through the media the point is in, unbroken */
	float3 tr = media_transmittance(sc, &l, x, wi, dist, key, dim + 3);
	return tr * light_emitted(sc, e->prim, pos, wi, dist) * f * (light_power_heuristic(pdf_light, pdf_bsdf) / pdf_light);
}
