/* integrator_path.cl: the path tracer. One work item per pixel; each launch adds
 * samples_per_pass samples to the pixel's running sum in film, so the image
 * converges progressively on the device and the host reads it when it wants.
 *
 * INTEGRATOR_PATH: next-event estimation at every vertex (all light_sources, one
 * emissive primitive chosen by power) and BSDF sampling, the two weighted by the
 * power heuristic where both can find the same light; Russian roulette after
 * three bounces. INTEGRATOR_NAIVE: the reference paper's algorithm, emitters found
 * only by the bounce rays (light_sources, which no ray can hit, are still sampled). */

#define RR_DEPTH 3

/* Dimensions of one bounce: 0-1 lobe choice and direction (with 2: u.z), 3 roulette,
 * 4-6 the emitter, 8 on: the light_sources' area samples. */
#define DIM_LOBE 0
#define DIM_ROULETTE 3
#define DIM_EMITTER 4
#define DIM_AREA 8

/* What the camera ray found first, for the AOVs. */
typedef struct {
	float3 albedo, normal;
	float depth;
	int object;    /* -1: nothing */
} first_hit;

inline float3 path_radiance(global const bvh_node *nodes, global const dev_prim *prims,
                            global const float4 *normals, global const dev_material *materials,
                            global const dev_light *lights, global const dev_emitter *emitters,
                            global const dev_params *p, int px, int py, uint key, uint *counts,
                            first_hit *first)
{
	float3 d = camera_ray_dir(p, px, py, rng_uniform(key, 0), rng_uniform(key, 1));
	float3 o = camera_lens(p, &d, light_square_to_disc(rng_uniform(key, 2), rng_uniform(key, 3)));
	float3 radiance = (float3)(0.0f), beta = (float3)(1.0f), sigma = (float3)(0.0f);
	float last_pdf = 0.0f;   /* 0: the last bounce was a single direction, or the camera */
	counts[COUNT_RAYS + RAY_CAMERA]++;
	for (int depth = 0;; depth++) {
		traverse_hit hit = traverse_closest(nodes, prims, p->n_prims, p->n_planes, o, d, 0.0f,
		                                    INFINITY, counts, depth == 0 ? RAY_CAMERA : RAY_BOUNCE);
		if (hit.prim < 0) {
			radiance += beta * p->background.xyz;
			break;
		}
		if (sigma.x > 0.0f || sigma.y > 0.0f || sigma.z > 0.0f)
			beta *= exp(-sigma * hit.t);   /* Beer-Lambert inside an absorbing interior */
		float3 x = o + hit.t * d;
		intersect_surface surf = intersect_surface_at(prims, normals, hit.prim, hit.inst, x);
		global const dev_material *m = &materials[surf.material];
		bool entering = dot(surf.ng, d) < 0.0f;
		/* surfaces are two-sided, as in POV-Ray: both normals turn to face the ray */
		float3 ng = entering ? surf.ng : -surf.ng, n = entering ? surf.ns : -surf.ns;
		float3 wo = -d;
		if (depth == 0) {
			first->albedo = clamp(m->diffuse.xyz + m->reflect.xyz + m->absorb.w * m->transmit.xyz, 0.0f, 1.0f);
			first->normal = n;
			first->depth = hit.t;
			first->object = surf.object;
		}

		if (surf.emitter >= 0) {
			float w = 1.0f;
			if (p->integrator == INTEGRATOR_PATH && last_pdf > 0.0f)
				w = light_power_heuristic(last_pdf, light_pdf(emitters, &prims[hit.prim], o, d, hit.t));
			radiance += beta * w * m->emission.xyz;
		} else {
			radiance += beta * m->emission.xyz;
		}
		if (depth >= p->max_depth)
			break;

		material_lobes lobes = material_lobes_at(m, dot(n, wo), entering);
		/* Leave the surface by a margin relative to the coordinates' magnitude, so
		 * the next ray does not find the surface it starts on. */
		float eps = 1e-4f * fmax(1.0f, fmax(fabs(x.x), fmax(fabs(x.y), fabs(x.z))));
		float3 xa = x + eps * ng;   /* above the surface, on the side the ray came from */
		uint dim = RNG_DIMS_PER_BOUNCE * (uint)(depth + 1);
		radiance += beta * light_pov(nodes, prims, lights, p, m, &lobes, xa, ng, n, wo, key,
		                             dim + DIM_AREA, counts);
		if (p->integrator == INTEGRATOR_PATH)
			radiance += beta * light_emitters(nodes, prims, materials, emitters, p, m, &lobes, xa,
			                                  ng, n, wo, key, dim + DIM_EMITTER, counts);

		float3 u = (float3)(rng_uniform(key, dim + DIM_LOBE), rng_uniform(key, dim + DIM_LOBE + 1),
		                    rng_uniform(key, dim + DIM_LOBE + 2));
		material_sample_t s = material_sample(m, &lobes, n, wo, entering, u);
		/* a shading normal can send a reflection below the true surface: lost */
		if ((s.weight.x <= 0.0f && s.weight.y <= 0.0f && s.weight.z <= 0.0f) ||
		    (dot(ng, s.wi) > 0.0f) == (bool)s.transmitted)
			break;
		beta *= s.weight;
		last_pdf = s.pdf;
		if (s.transmitted) {
			o = x - eps * ng;
			sigma = entering ? m->absorb.xyz : (float3)(0.0f);
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
		counts[COUNT_RAYS + RAY_BOUNCE]++;
	}
	return radiance;
}

/* The camera rays' node and primitive tests so far: the heat map's measure, as in
 * the reference paper's figure (--stats counts every kind of ray). */
inline uint path_tests(const uint *counts)
{
	return counts[COUNT_NODES + RAY_CAMERA] + counts[COUNT_PRIMS + RAY_CAMERA];
}

kernel void render_pass(global const bvh_node *nodes, global const dev_prim *prims,
                        global const float4 *normals, global const dev_material *materials,
                        global const dev_light *lights,
                        global const dev_emitter *emitters, global const dev_params *p,
                        global float4 *film, global uint *counters, global float4 *aov,
                        global const dev_finish *finishes, global const int *objects)
{
	int pixel = get_global_id(0);
	if (pixel >= p->width * p->height)
		return;
	int px = pixel % p->width, py = pixel / p->width;
	uint counts[COUNT_N] = { 0 };
	float4 acc = film[pixel];
	float4 a0 = 0.0f, a1 = 0.0f, a2 = 0.0f;
	if (p->aov) {
		a0 = aov[AOV_FLOAT4S * pixel];
		a1 = aov[AOV_FLOAT4S * pixel + 1];
		a2 = aov[AOV_FLOAT4S * pixel + 2];
	}
	for (int s = 0; s < p->samples_per_pass; s++) {
		uint key = rng_key((uint)pixel, (uint)(p->sample_base + s), (uint)p->seed);
		uint tests = path_tests(counts);
		first_hit first = { (float3)(0.0f), (float3)(0.0f), 0.0f, -1 };
		float3 l = path_radiance(nodes, prims, normals, materials, lights, emitters, p, px, py, key,
		                         counts, &first);
		if (first.object >= 0) {
			a0 += (float4)(first.albedo, 1.0f);
			a1 += (float4)(first.normal, 0.0f);
			a2.x += first.depth;
		}
		if (p->sample_base + s == 0)
			a2.y = (float)first.object;
		/* one bad sample (a NaN from a degenerate hit) must not blacken the pixel */
		if (!(isfinite(l.x) && isfinite(l.y) && isfinite(l.z)))
			l = (float3)(0.0f);
		/* sample by sample, so the sums do not depend on how samples group into passes */
		acc += (float4)(l, (float)(path_tests(counts) - tests));
	}
	film[pixel] = acc;
	if (p->aov) {
		aov[AOV_FLOAT4S * pixel] = a0;
		aov[AOV_FLOAT4S * pixel + 1] = a1;
		aov[AOV_FLOAT4S * pixel + 2] = a2;
	}
	for (int i = 0; i < COUNT_N; i++)
		atomic_add(&counters[i], counts[i]);
}
