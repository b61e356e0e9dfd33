/* texture.cl: what a surface looks like at one point. An integrator that finds
 * a hit makes its shading_point once (texture_point), and everything after
 * reads from it: the material, the pigment evaluated there (texture_pigment),
 * the AOVs. Patterns (pattern.cl) give a value; the pattern's map turns the
 * value into a colour, or into nested pigments whose colours blend by weight. */

typedef struct {
	float3 x;          /* the hit, in world space */
	float3 object_x;      /* in its instance's space (a mesh's), else x */
	float3 ng, ns;     /* geometric and shading normals, turned to face the ray (the
	                    * shading one before its normal pattern's tilt) */
	float3 d;          /* the ray's direction */
	float t;           /* its distance along the ray */
	float eps;         /* how far rays leaving the surface start off it */
	int prim, object;
	int emitter;       /* the emitter table's entry, or -1 */
	bool entering;     /* the ray meets the side the geometric normal points to */
	global const dev_material *m;
} shading_point;

/* POV-Ray's colour: rgb, and the light it lets through, filtered by the colour
 * (filter) or not (transmit). */
typedef struct {
	float3 rgb;
	float filter, transmit;
} pigment_colour;

inline shading_point texture_point(const scene_data *sc, traverse_hit hit, float3 o, float3 d)
{
	shading_point sp;
	sp.x = o + hit.t * d;
	intersect_surface s = intersect_surface_at(sc->prims, sc->normals, hit.prim, hit.inst, sp.x);
	sp.object_x = s.object_x;
	sp.entering = dot(s.ng, d) < 0.0f;
	/* surfaces are two-sided, as in POV-Ray: both normals turn to face the ray */
	sp.ng = sp.entering ? s.ng : -s.ng;
	/* the shading normal faces the ray before a normal pattern tilts it, as
	 * POV-Ray orients it; the tilt may then turn it a little away */
	sp.ns = dot(s.ns, d) > 0.0f ? -s.ns : s.ns;
	sp.d = d;
	sp.t = hit.t;
	/* a margin relative to the coordinates' magnitude, so that the next ray does
	 * not find the surface it starts on */
	sp.eps = 1e-4f * fmax(1.0f, fmax(fabs(sp.x.x), fmax(fabs(sp.x.y), fabs(sp.x.z))));
	sp.prim = hit.prim;
	sp.object = s.object;
	sp.emitter = s.emitter;
	sp.m = &sc->materials[s.material];
	/* the normal's pattern tilts the shading normal (a mesh's own textures'
	 * normals are not applied yet: lower_texture.c says so) */
	if (sp.m->normal >= 0 && !(sp.m->flags & MATERIAL_LOCAL))
		sp.ns = pattern_perturb(&sc->patterns[sp.m->normal], sc->warps, sc->maps, sp.x, sp.ns);
	return sp;
}

/* POV-Ray's blend map search: the entries around v, and how far v is from the
 * first to the second (Search_Blend_Map: past the last entry, the last; at or
 * before the first, the first; an entry's own value gives that entry). */
inline int texture_map_search(global const dev_map_entry *e, int n, float v, int *next, float *frac)
{
	*frac = 0.0f;
	if (v >= e[n - 1].value) {
		*next = n - 1;
		return n - 1;
	}
	int c = 0;
	while (v > e[c].value)
		c++;
	*next = c;
	if (c == 0)
		return 0;
	*frac = (v - e[c - 1].value) / (e[c].value - e[c - 1].value);
	return c - 1;
}

#define TEXTURE_STACK 8   /* nested pigments waiting; lower.c keeps maps shallower */

/* The pigment at the shading point: the solid colour, or the pattern's map at
 * the pattern's value there, nested pigments evaluated and blended in turn. */
inline pigment_colour texture_pigment(const scene_data *sc, const shading_point *sp)
{
	global const dev_material *m = sp->m;
	pigment_colour out = { m->pigment.xyz, m->pigment.w, m->ambient.w };
	if (m->pattern < 0)
		return out;
	float3 p = m->flags & MATERIAL_LOCAL ? sp->object_x : sp->x;
	int stack[TEXTURE_STACK];
	float weight[TEXTURE_STACK];
	int n = 0;
	stack[n] = m->pattern;
	weight[n++] = 1.0f;
	float4 sum = (float4)(0.0f);
	float transmit = 0.0f;
	while (n > 0) {
		n--;
		global const dev_pattern *pt = &sc->patterns[stack[n]];
		float w = weight[n], v = 0.0f;
		if (pt->kind != PATTERN_SOLID) {
			float3 q = (float3)(dot(pt->rows[0].xyz, p) + pt->rows[0].w, dot(pt->rows[1].xyz, p) + pt->rows[1].w,
			                    dot(pt->rows[2].xyz, p) + pt->rows[2].w);
			v = pattern_value(pt, sc->warps, q, sp->ns, sp->d);
		}
		global const dev_map_entry *e = sc->maps + pt->map_first;
		int b;
		float f;
		int a = texture_map_search(e, pt->map_count, v, &b, &f);
		int idx[2] = { a, b };
		float wt[2] = { a == b ? 1.0f : 1.0f - f, a == b ? 0.0f : f };
		for (int k = 0; k < 2; k++) {
			if (wt[k] <= 0.0f)
				continue;
			global const dev_map_entry *x = &e[idx[k]];
			if (x->pigment >= 0 && n < TEXTURE_STACK) {
				stack[n] = x->pigment;
				weight[n++] = w * wt[k];
			} else {
				sum += w * wt[k] * x->colour;
				transmit += w * wt[k] * x->transmit;
			}
		}
	}
	out.rgb = sum.xyz;
	out.filter = sum.w;
	out.transmit = transmit;
	return out;
}

/* What a ray that leaves the scene sees: the sky_sphere's pigments at the
 * point of the unit sphere the ray points to, the last written on top, each
 * showing what is below through its filter and transmit, and the background
 * below them all (POV-Ray 3.7's sky, with its emission in the layers'). */
inline float3 texture_sky(const scene_data *sc, float3 d)
{
	global const dev_params *p = sc->p;
	float3 col = (float3)(0.0f), through = (float3)(1.0f);
	shading_point sp;
	sp.x = sp.object_x = d;
	sp.ng = sp.ns = -d;
	sp.d = d;
	for (int i = p->sky + p->sky_layers - 1; p->sky >= 0 && i >= p->sky; i--) {
		sp.m = &sc->materials[i];
		pigment_colour c = texture_pigment(sc, &sp);
		col += c.rgb * (1.0f - c.filter - c.transmit) * through * sp.m->emission.xyz;
		through *= c.filter * c.rgb + c.transmit;
	}
	return col + p->background.xyz * through;
}

inline void texture_first_hit(first_hit *first, const shading_point *sp, float3 albedo)
{
	if (first->object >= 0)
		return;
	first->albedo = albedo;
	first->normal = sp->ns;
	first->depth = sp->t;
	first->object = sp->object;
}
