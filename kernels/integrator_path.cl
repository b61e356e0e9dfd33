/* integrator_path.cl: the path tracer. One work item per pixel; each launch adds
 * samples_per_pass samples to the pixel's running sum in film, so the image
 * converges progressively on the device and the host reads it when it wants.
 *
 * INTEGRATOR_PATH: next-event estimation at every vertex (all light_sources, one
 * emissive primitive chosen by power, the sky when it is an image: light_sky) and BSDF sampling, the two weighted by the
 * power heuristic where both can find the same light; Russian roulette after
 * three bounces. INTEGRATOR_NAIVE: the reference paper's algorithm, emitters found
 * only by the bounce rays (light_sources, which no ray can hit, are still sampled). */

#define RR_DEPTH 3

/* Dimensions of one bounce: 0-1 lobe choice and direction (with 2: u.z), 3 roulette,
 * 4-6 the emitter, 7 the texture (texture_choose), 8 on: the light_sources' area samples. */
#define DIM_LOBE 0
#define DIM_ROULETTE 3
#define DIM_EMITTER 4
#define DIM_TEXTURE 7
#define DIM_AREA 8
#define DIM_MEDIA 40   /* 40: the walk's chain; 41-43 the phase; 44 on: the vertex's lights */
/* The sky's (light_sky), eight a bounce in a range of their own, past any the
 * lights' counts reach. */
#define DIM_SKY 0x40000000u
/* crand's, one a bounce. */
#define DIM_CRAND 0x50000000u
/* The rainbows' jitter: a key a bounce, a dimension a rainbow. */
#define DIM_RAINBOW 0x60000000u

/* The objects a ray of this bounce may not see: POV-Ray's no_image for the
 * camera's, no_reflection after a reflection. */
static inline int path_skip(int depth, bool reflected)
{
	return depth == 0 ? OBJECT_NO_IMAGE : reflected ? OBJECT_NO_REFLECTION : 0;
}

static inline float3 path_radiance(const scene_data *sc, int px, int py, uint key, first_hit *first, float *transm)
{
	global const dev_params *p = sc->p;
	float3 o, d;
	float2 xy;
	if (!camera_view(sc, px, py, rng_uniform(key, 0), rng_uniform(key, 1), &o, &d, &xy))
		return (float3)(0.0f);   /* no ray there: POV-Ray's pixel is black */
	o = camera_lens(p, o, &d, light_square_to_disc(rng_uniform(key, 2), rng_uniform(key, 3)));
	d = camera_perturb(sc, xy, d);
	float3 radiance = (float3)(0.0f), beta = (float3)(1.0f), sigma = (float3)(0.0f);
	float last_pdf = 0.0f;   /* 0: the last bounce was a single direction, or the camera */
	bool reflected = false;
	bool sky_mis = false;   /* the last vertex sampled the sky too: a ray that leaves shares its weight */
	int solids = p->camera_solids;   /* solid objects around the ray: no fog in them */
	media_stack ms = media_around(sc, p->cam_location.xyz);   /* the interiors with media around the ray */
	sc->counts[COUNT_RAYS + RAY_CAMERA]++;
	for (int depth = 0;; depth++) {
		traverse_hit hit = visibility_closest(sc, o, d, 0.0f, depth == 0 ? camera_max_distance(sc) : INFINITY,
		                                      path_skip(depth, reflected),
		                                      depth == 0 ? RAY_CAMERA : RAY_BOUNCE);
		uint dim = RNG_DIMS_PER_BOUNCE * (uint)(depth + 1);
		media_list ml = media_list_at(sc, &ms, solids);
		media_walk walk = media_track(sc, &ml, o, d, hit.prim < 0 ? INFINITY : hit.t, &beta, &radiance, key,
		                              dim + DIM_MEDIA);
		float seg = walk.event ? walk.t : hit.prim < 0 ? INFINITY : hit.t;
		if (solids == 0 && p->n_fogs > 0) {   /* the fogs' emission and absorption over the segment */
			fog_effect fe = fog_segment(sc, o, d, seg, false);
			radiance += beta * fe.add;
			beta *= fe.att;
		}
		float rainbow_transm = 1.0f;   /* what the rainbows leave of the alpha channel's background */
		if (solids == 0 && p->n_rainbows > 0) {   /* the rainbows' colour over the segment, inside the fogs */
			rainbow_effect re = rainbow_segment(sc, d, seg, rng_hash(key ^ rng_hash(DIM_RAINBOW + (uint)depth)));
			radiance += beta * re.add;
			beta *= re.att;
			rainbow_transm = re.transm;
		}
		if (sigma.x > 0.0f || sigma.y > 0.0f || sigma.z > 0.0f)
			beta *= exp(-sigma * fmin(seg, 1e30f));   /* Beer-Lambert inside an absorbing interior */
		if (walk.event == 2)
			break;
		if (walk.event == 1) {   /* a vertex in the media: lights, then the phase function */
			float3 x = o + walk.t * d;
			if (depth >= p->max_depth)
				break;
			radiance += beta * media_vertex_lights(sc, &ml, ms, solids, x, d, key, dim + DIM_MEDIA + 4);
			float3 u = (float3)(rng_uniform(key, dim + DIM_MEDIA + 1), rng_uniform(key, dim + DIM_MEDIA + 2),
			                    rng_uniform(key, dim + DIM_MEDIA + 3));
			float3 wi = media_phase_sample(sc, &ml, x, d, u);
			float pdf;
			float3 f = media_scatter_eval(sc, &ml, x, d, wi, &pdf);
			if (!(pdf > 0.0f))
				break;
			beta *= f / pdf;
			last_pdf = pdf;
			reflected = false;
			sky_mis = false;
			o = x;
			d = wi;
			if (depth + 1 >= RR_DEPTH) {
				float q = clamp(fmax(beta.x, fmax(beta.y, beta.z)), 0.05f, 0.95f);
				if (rng_uniform(key, dim + DIM_ROULETTE) >= q)
					break;
				beta /= q;
			}
			sc->counts[COUNT_RAYS + RAY_BOUNCE]++;
			continue;
		}
		if (hit.prim < 0) {
			float w = 1.0f;
			if (sky_mis && last_pdf > 0.0f)
				w = light_power_heuristic(last_pdf, sky_pdf(sc->sky_dist, sc->sky_cdf, d));
			radiance += beta * w * texture_sky(sc, d, depth == 0);
			if (depth == 0)   /* the camera ray that meets nothing shows the background */
				*transm = texture_sky_transm(sc, d) * rainbow_transm;
			break;
		}
		shading_point sp = texture_point(sc, hit, o, d);
		float3 tint = (float3)(1.0f);   /* through the layers above the chosen one */
		pigment_colour pc = texture_choose(sc, &sp, rng_uniform(key, dim + DIM_TEXTURE), &tint);
		beta *= tint;
		bsdf m = material_bsdf(sp.m, pc.rgb, pc.filter, pc.transmit);
		float3 ng = sp.ng, n = sp.ns, wo = -d, x = sp.x;
		if (m.irid.x > 0.0f)
			m.irid.y = finish_irid_thickness(sp.m, x);
		if (sp.m->irid.w > 0.0f && sp.m->emission.w > 0.0f)   /* crand: POV-Ray's u * crand off diffuse */
			m.diffuse *= fmax(0.0f, 1.0f - rng_uniform(key, DIM_CRAND + (uint)depth) * sp.m->irid.w / sp.m->emission.w);
		texture_first_hit(first, &sp, clamp(m.diffuse + m.reflect.xyz + m.absorb.w * m.transmit.xyz, 0.0f, 1.0f));

		if (sp.emitter >= 0) {
			float w = 1.0f;
			if (p->integrator == INTEGRATOR_PATH && last_pdf > 0.0f)
				w = light_power_heuristic(last_pdf, light_pdf(sc, &sc->emitters[sp.emitter], o, d, hit.t));
			radiance += beta * w * m.emission;
		} else {
			radiance += beta * m.emission;
		}
		if (depth >= p->max_depth)
			break;

		material_lobes lobes = material_lobes_at(&m, dot(n, wo), sp.entering);
		float3 xa = x + sp.eps * ng;   /* above the surface, on the side the ray came from */
		radiance += beta * light_pov(sc, &m, &lobes, xa, ng, n, wo, key, dim + DIM_AREA, solids, ms);
		if (p->integrator == INTEGRATOR_PATH)
			radiance += beta * light_emitters(sc, &m, &lobes, xa, ng, n, wo, key, dim + DIM_EMITTER, ms, solids);
		sky_mis = p->integrator == INTEGRATOR_PATH && p->sky_sampled;
		if (sky_mis)
			radiance += beta * light_sky(sc, &m, &lobes, xa, ng, n, wo, key, DIM_SKY + 8u * (uint)depth, ms, solids);

		float3 u = (float3)(rng_uniform(key, dim + DIM_LOBE), rng_uniform(key, dim + DIM_LOBE + 1),
		                    rng_uniform(key, dim + DIM_LOBE + 2));
		material_sample_t s = material_sample(&m, &lobes, n, wo, sp.entering, u);
		if (s.weight.x <= 0.0f && s.weight.y <= 0.0f && s.weight.z <= 0.0f)
			break;
		/* A shading normal (smooth, or tilted by a normal pattern) can send a
		 * reflection below the true surface, or a transmission above it: mirror
		 * it back across the surface, keeping its weight, so that bumps neither
		 * lose nor make energy (the white furnace stays at 1). */
		if ((dot(ng, s.wi) > 0.0f) == (bool)s.transmitted)
			s.wi -= 2.0f * dot(s.wi, ng) * ng;
		beta *= s.weight;
		last_pdf = s.pdf;
		reflected = !s.transmitted;
		if (s.transmitted) {
			if (!(sc->objects[sp.object] & OBJECT_HOLLOW))
				solids = sp.entering ? solids + 1 : max(solids - 1, 0);
			o = x - sp.eps * ng;
			sigma = sp.entering ? m.absorb.xyz : (float3)(0.0f);
			ms = media_cross(ms, &sc->materials[sp.material]);
		} else {
			o = xa;
		}
		d = s.wi;
		if (depth + 1 >= RR_DEPTH) {
			float q = clamp(fmax(beta.x, fmax(beta.y, beta.z)), 0.05f, 0.95f);
			if (rng_uniform(key, dim + DIM_ROULETTE) >= q)
				break;
			beta /= q;
		}
		sc->counts[COUNT_RAYS + RAY_BOUNCE]++;
	}
	return radiance;
}

/* The camera rays' node and primitive tests so far: the heat map's measure, as in
 * the reference paper's figure (--stats counts every kind of ray). */
static inline uint path_tests(const uint *counts)
{
	return counts[COUNT_NODES + RAY_CAMERA] + counts[COUNT_PRIMS + RAY_CAMERA];
}

#if !defined(KERNELS_SOME) || defined(KERNELS_PATH)   /* lower_kernel_options: the kernels a render launches */
kernel void render_pass(SCENE_BUFFERS(SCENE_PARAM) global const dev_params *p, global long4 *film,
                        global uint *counters, global float4 *aov)
{
	int pixel = get_global_id(0);
	if (pixel >= p->width * p->height)
		return;
	int px = pixel % p->width, py = pixel / p->width;
	uint counts[COUNT_N] = { 0 };
	scene_data sc = { SCENE_BUFFERS(SCENE_FIELD) p, counts };
	long4 acc = film[pixel];
	for (int s = 0; s < p->samples_per_pass; s++) {
		uint key = rng_key((uint)pixel, (uint)(p->sample_base + s), (uint)p->seed);
		uint tests = path_tests(counts);
		first_hit first = { (float3)(0.0f), (float3)(0.0f), 0.0f, -1 };
		float transm = 0.0f;
		float3 l = film_finite(path_radiance(&sc, px, py, key, &first, &transm));
		if (p->aov) {
			film_add_aov(aov, pixel, &first, p->sample_base + s);
			film_add_transm(aov, pixel, transm);
		}
		/* sample by sample, so the sums do not depend on how samples group into passes */
		acc += film_fixed(l, path_tests(counts) - tests);
	}
	film[pixel] = acc;
	film_add_counts(counters, counts);
}
#endif
