/* normal.cl: POV-Ray 3.7's normal perturbation, normal { PATTERN [Amount] },
 * evaluated on the device (POV-Ray's Perturb_Normal).
 *
 * The normal is taken into the pattern's space (by the inverse transpose of
 * each transformation), perturbed there at the warped point, and brought back.
 * Bumps, dents, ripples, waves, wrinkles, quilted and facets have normal
 * functions of their own, as in POV-Ray 3.7 (its patterns up to
 * LAST_NORM_ONLY_PATTERN); every other pattern tilts the normal by its value
 * at four points of a pyramid around the warped point, `accuracy` away, with
 * frequency, phase and wave type applied, through the slope_map if any.
 * normal_map and the other normals of normals are texture.cl's texture_normal.
 * A bump_map reads its image: texture.cl's texture_perturb, with
 * normal_warp_in and normal_warp_out around image.cl's image_bump.
 *
 * Exported: pattern_perturb, normal_warp_in, normal_warp_out. */

/* POV-Ray's pyramid: four unit vectors that sum to zero. */
constant float4 normal_pyramid[4] = {
	(float4)(0.942809041f, -0.333333333f, 0.0f, 0.0f),
	(float4)(-0.471404521f, -0.333333333f, 0.816496581f, 0.0f),
	(float4)(-0.471404521f, -0.333333333f, -0.816496581f, 0.0f),
	(float4)(0.0f, 1.0f, 0.0f, 0.0f),
};

/* A world-space normal taken into the space an affine map's rows a, b, c lead
 * to: the inverse transpose of the linear part, from its cofactors. */
static inline float3 normal_into(float4 a, float4 b, float4 c, float3 n)
{
	float3 c0 = cross(b.xyz, c.xyz), c1 = cross(c.xyz, a.xyz), c2 = cross(a.xyz, b.xyz);
	float det = dot(a.xyz, c0);
	return (float3)(dot(c0, n), dot(c1, n), dot(c2, n)) / det;
}

/* Back out of that space: the transpose of the linear part. */
static inline float3 normal_out_of(float4 a, float4 b, float4 c, float3 v)
{
	return v.x * a.xyz + v.y * b.xyz + v.z * c.xyz;
}

/* POV-Ray's Do_Slope_Map: the value through the slope_map's Hermite cubics,
 * between two entries (height colour.x, slope colour.y); at or beyond an end,
 * or on an entry, that entry's height. */
static inline float normal_slope_map(global const dev_map_entry *e, int n, float v)
{
	if (n <= 0)
		return v;
	int c = 0;
	if (v >= e[n - 1].value)
		c = n - 1;
	else
		while (v > e[c].value)
			c++;
	if (c == 0 || v == e[c].value || v >= e[n - 1].value)
		return e[c].colour.x;
	float2 a = e[c - 1].colour.xy, b = e[c].colour.xy;
	float t = (v - e[c - 1].value) / (e[c].value - e[c - 1].value);
	float tt = t * t, ttt = tt * t;
	return ttt * (a.y + b.y + 2.0f * (a.x - b.x)) - tt * (2.0f * a.y + b.y + 3.0f * (a.x - b.x)) + t * a.y + a.x;
}

/* Facets, POV-Ray's: the nearest of the random points (crackle's, one per unit
 * cube) to the normal scaled by 1 / size, or with coords to the point scaled
 * so; without coords that point becomes the normal, with coords the normal
 * tilts by coords times DNoise there, less its part along the normal. */
static inline float3 normal_facets(float4 prm, float3 p, float3 v)
{
	float size = prm.x, coords = prm.y, metric = prm.z;
	v = normalize(v);
	float3 tv = (coords != 0.0f ? p : v) * (size < 1e-6f ? 1e6f : 1.0f / size);
	int fx = (int)floor(tv.x - 1e-10f), fy = (int)floor(tv.y - 1e-10f), fz = (int)floor(tv.z - 1e-10f);
	float best = 0.0f;
	float3 nearest = (float3)(0.0f);
	int first = 1;
	for (int ax = -2; ax <= 2; ax++)
		for (int ay = -2; ay <= 2; ay++)
			for (int az = -2; az <= 2; az++) {
				if ((abs(ax) == 2) + (abs(ay) == 2) + (abs(az) == 2) > 1)
					continue;
				int cx = fx + ax, cy = fy + ay, cz = fz + az;
				float3 c = pattern_cell_point(cx, cy, cz);
				float3 d = c - tv;
				float sum;
				if (metric == 2.0f)
					sum = dot(d, d);
				else if (metric == 1.0f)
					sum = d.x + d.y + d.z;   /* POV-Ray's: signed, no fabs */
				else
					sum = pow(fabs(d.x), metric) + pow(fabs(d.y), metric) + pow(fabs(d.z), metric);
				if (first || sum < best) {
					best = sum;
					nearest = c;
					first = 0;
				}
			}
	if (coords == 0.0f)
		return nearest;
	float3 pert = pattern_dnoise(nearest, 0);
	pert -= v * dot(pert, v);
	return v + coords * pert;
}

/* POV-Ray's Warp_Normal: the world-space normal n into pt's space, through
 * every transformation in the warps' order, the pattern's own (rows) first;
 * unit length unless no_bump_scale. */
static float3 normal_warp_in(global const dev_pattern *pt, global const dev_warp *warps, float3 n)
{
	int scale_bumps = !(pt->flags & PATTERN_NO_BUMP_SCALE);
	float3 v = scale_bumps ? normalize(n) : n;
	v = normal_into(pt->rows[0], pt->rows[1], pt->rows[2], v);
	for (int i = 0; i < pt->warp_count; i++) {
		global const dev_warp *w = &warps[pt->warp_first + i];
		if (w->kind == WARP_TRANSFORM)
			v = normal_into(w->a, w->b, w->c, v);
	}
	return scale_bumps ? normalize(v) : v;
}

/* POV-Ray's UnWarp_Normal: back through the transformations in reverse
 * order, to a unit normal in world space. */
static float3 normal_warp_out(global const dev_pattern *pt, global const dev_warp *warps, float3 v)
{
	for (int i = pt->warp_count - 1; i >= 0; i--) {
		global const dev_warp *w = &warps[pt->warp_first + i];
		if (w->kind == WARP_TRANSFORM)
			v = normal_out_of(w->a, w->b, w->c, v);
	}
	v = normal_out_of(pt->rows[0], pt->rows[1], pt->rows[2], v);
	return normalize(v);
}

/* The normal n (unit, world space, facing the ray) perturbed at p (world
 * space) by the normal pattern pt, with its warps and its slope_map (maps,
 * from pt->map_first): the unit perturbed normal in world space. */
static float3 pattern_perturb(const scene_data *sc, global const dev_pattern *pt, float3 p, float3 n)
{
	global const dev_warp *warps = sc->warps;
	global const dev_map_entry *maps = sc->maps;
	int kind = pt->kind;
	if (kind == PATTERN_SOLID || kind == PATTERN_AOI || (pt->flags & PATTERN_NORMAL_MAP))
		return normalize(n);   /* aoi: the same value at the four points, no slope; normals of
		                        * normals: texture_normal, one level deep */
	float4 r0 = pt->rows[0], r1 = pt->rows[1], r2 = pt->rows[2];
	float3 q = (float3)(dot(r0.xyz, p) + r0.w, dot(r1.xyz, p) + r1.w, dot(r2.xyz, p) + r2.w);
	float amount = pt->bump_size;
	float3 v = normal_warp_in(pt, warps, n);

	float3 t = pattern_warp_point(pt, warps, q);
	int generator = pt->noise_generator;
	if (generator < 1 || generator > 3)
		generator = 2;

	switch (kind) {
	case PATTERN_BUMPS:
		v += amount * pattern_dnoise(t, 0);
		break;
	case PATTERN_DENTS: {
		float s = pattern_noise(t, generator);
		v += s * s * s * amount * pattern_dnoise(t, 0);
		break;
	}
	case PATTERN_RIPPLES:
	case PATTERN_WAVES: {
		int n_waves = pt->params[0].x >= 1.0f ? (int)pt->params[0].x : 10;
		uint r = PATTERN_WAVE_SEED;
		for (int i = 0; i < n_waves; i++) {
			float wf;
			float3 d = t - pattern_wave_source(i, &r, &wf);
			float len = length(d);
			if (len == 0.0f)
				len = 1.0f;
			float s = kind == PATTERN_RIPPLES
			        ? pattern_cycloidal(len * pt->frequency + pt->phase) * amount
			        : pattern_cycloidal(len * pt->frequency * wf + pt->phase) * amount / wf;
			v += (s / (len * (float)n_waves)) * d;
		}
		break;
	}
	case PATTERN_WRINKLES: {
		float3 sum = (float3)(0.0f);
		float scale = 1.0f;
		for (int i = 0; i < 10; i++, scale *= 2.0f)
			sum += fabs(pattern_dnoise(t * scale, 0) / scale);
		v += amount * sum;
		break;
	}
	case PATTERN_QUILTED: {
		float3 c = (float3)(t.x - pattern_floor_pov(t.x), t.y - pattern_floor_pov(t.y),
		                    t.z - pattern_floor_pov(t.z)) - 0.5f;
		float l = length(c), il = 1.0f - l, c0 = pt->params[0].x, c1 = pt->params[0].y;
		float k = (l * l * l + 3.0f * l * il * il * c0 + 3.0f * l * l * il * c1) * 1.154700538f;
		v += amount * (c * k);
		break;
	}
	case PATTERN_FACETS:
		v = normal_facets(pt->params[0], t, v);
		break;
	default: {
		/* POV-Ray's slope: the fudge factor -5, and the accuracy's. */
		float accuracy = pt->normal.x;
		float k = amount * -5.0f * (0.02f / accuracy);
		global const dev_map_entry *e = maps + pt->map_first;
		float3 sum = (float3)(0.0f);
		for (int i = 0; i < 4; i++) {
			float3 dir = normal_pyramid[i].xyz;
			float val = pattern_at(sc, pt, t + accuracy * dir, n, -n);
			sum += normal_slope_map(e, pt->map_count, val) * dir;
		}
		v += k * sum;
		break;
	}
	}

	return normal_warp_out(pt, warps, v);
}
