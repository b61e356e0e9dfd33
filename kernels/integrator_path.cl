/* integrator_path.cl: the path tracer. One work item per pixel; each launch adds
 * samples_per_pass samples to the pixel's running sum in accum, so the image
 * converges progressively on the device and the host reads it back once. */

/* POV-Ray's point light without distance falloff: a white light of colour C on a
 * surface of albedo a at angle theta is seen as a * C * cos(theta), which is a
 * Lambertian surface under irradiance pi * C * cos(theta). */
inline float3 direct_point_lights(global const bvh_node *nodes, global const dev_prim *prims,
                                  global const dev_light *lights, global const dev_params *p,
                                  float3 x, float3 n, float3 albedo, uint *tests)
{
	float3 sum = (float3)(0.0f);
	for (int i = 0; i < p->n_lights; i++) {
		float3 to = lights[i].position.xyz - x;
		float dist = length(to);
		float3 l = to / dist;
		float c = dot(n, l);
		if (c <= 0.0f || dist == 0.0f)
			continue;
		if (!traverse_any(nodes, prims, p->n_prims, x, l, 0.0f, dist, tests))
			sum += albedo * lights[i].color.xyz * c;
	}
	return sum;
}

inline float3 path_radiance(global const bvh_node *nodes, global const dev_prim *prims,
                            global const dev_material *materials, global const dev_light *lights,
                            global const dev_params *p, int px, int py, uint key, uint *tests)
{
	float3 o = p->cam_location.xyz;
	float3 d = camera_ray_dir(p, px, py, rng_uniform(key, 0), rng_uniform(key, 1));
	float3 radiance = (float3)(0.0f), beta = (float3)(1.0f);
	for (int depth = 0;; depth++) {
		traverse_hit hit = traverse_closest(nodes, prims, p->n_prims, o, d, 0.0f, INFINITY, tests);
		if (hit.prim < 0) {
			radiance += beta * p->background.xyz;
			break;
		}
		global const dev_prim *prim = &prims[hit.prim];
		global const dev_material *m = &materials[prim->material];
		float3 x = o + hit.t * d;
		float3 n = prim_normal(prim, x);
		if (dot(n, d) > 0.0f)
			n = -n; /* surfaces are two-sided, as in POV-Ray */
		radiance += beta * m->emission.xyz;
		float3 albedo = m->albedo.xyz;
		if (depth >= p->max_depth || (albedo.x <= 0.0f && albedo.y <= 0.0f && albedo.z <= 0.0f))
			break;
		/* Leave the surface by a margin relative to the coordinates' magnitude, so
		 * the next ray does not find the surface it starts on. */
		float eps = 1e-4f * fmax(1.0f, fmax(fabs(x.x), fmax(fabs(x.y), fabs(x.z))));
		x += eps * n;
		radiance += beta * direct_point_lights(nodes, prims, lights, p, x, n, albedo, tests);
		uint dim = RNG_DIMS_PER_BOUNCE * (uint)(depth + 1);
		d = material_sample_cosine(n, rng_uniform(key, dim), rng_uniform(key, dim + 1));
		o = x;
		beta *= albedo;
	}
	return radiance;
}

kernel void render_pass(global const bvh_node *nodes, global const dev_prim *prims,
                        global const dev_material *materials, global const dev_light *lights,
                        global const dev_params *p, global float4 *accum)
{
	int pixel = get_global_id(0);
	if (pixel >= p->width * p->height)
		return;
	int px = pixel % p->width, py = pixel / p->width;
	float3 sum = (float3)(0.0f);
	uint tests = 0;
	for (int s = 0; s < p->samples_per_pass; s++) {
		uint key = rng_key((uint)pixel, (uint)(p->sample_base + s), (uint)p->seed);
		float3 l = path_radiance(nodes, prims, materials, lights, p, px, py, key, &tests);
		/* one bad sample (a NaN from a degenerate hit) must not blacken the pixel */
		if (isfinite(l.x) && isfinite(l.y) && isfinite(l.z))
			sum += l;
	}
	accum[pixel] += (float4)(sum, 0.0f);
}
