/* texture.cl: what a surface looks like at one point. An integrator that finds
 * a hit makes its shading_point once (texture_point), and everything after
 * reads from it: the material, the pigment evaluated there (texture_pigment),
 * the AOVs. Patterns (pattern.cl) give a value; the pattern's map turns the
 * value into a colour, or into nested pigments whose colours blend by weight.
 * A pattern of whole textures picks or blends materials (texture_blend_at);
 * a layered texture is a chain of materials, top first (dev_material.below).
 * texture_use makes one of those the shading point's material. */

typedef struct {
	float3 x;          /* the hit, in world space */
	float3 object_x;      /* in its instance's space (a mesh's), else x */
	float3 ng, ns;     /* geometric and shading normals, turned to face the ray (the
	                    * shading one before its normal pattern's tilt) */
	float3 n0;         /* the shading normal before any normal pattern's tilt */
	float2 uv;         /* the surface's uv (shape_uv), where a pattern is uv_mapped (SCENE_UV) */
	float3 d;          /* the ray's direction */
	float t;           /* its distance along the ray */
	float eps;         /* how far rays leaving the surface start off it */
	int prim, object;
	int emitter;       /* the emitter table's entry, or -1 */
	bool entering;     /* the ray meets the side the geometric normal points to */
	int material;      /* the surface's material (a pattern of textures, or a top layer) */
	global const dev_material *m;   /* the material being shaded (texture_use) */
} shading_point;

/* POV-Ray's colour: rgb, and the light it lets through, filtered by the colour
 * (filter) or not (transmit). */
typedef struct {
	float3 rgb;
	float filter, transmit;
} pigment_colour;

static float3 texture_normal(const scene_data *sc, int normal, float3 x, float2 uv, float3 n);

static inline shading_point texture_point(const scene_data *sc, traverse_hit hit, float3 o, float3 d)
{
	shading_point sp;
	sp.x = o + hit.t * d;
	intersect_surface s = intersect_surface_at(sc, sc->prims, sc->normals, hit.prim, hit.inst, hit.flip, sp.x);
	sp.object_x = s.object_x;
	sp.uv = sc->p->scene_flags & SCENE_UV ? shape_uv(sc->prims, sc->normals, hit.prim, hit.inst, s.object_x, sp.x)
	                                      : (float2)(0.0f);
	sp.entering = dot(s.ng, d) < 0.0f;
	/* surfaces are two-sided, as in POV-Ray: both normals turn to face the ray */
	sp.ng = sp.entering ? s.ng : -s.ng;
	/* the shading normal faces the ray before a normal pattern tilts it, as
	 * POV-Ray orients it; the tilt may then turn it a little away */
	sp.ns = dot(s.ns, d) > 0.0f ? -s.ns : s.ns;
	sp.n0 = sp.ns;
	sp.d = d;
	sp.t = hit.t;
	/* a margin relative to the coordinates' magnitude, so that the next ray does
	 * not find the surface it starts on */
	sp.eps = 1e-4f * fmax(1.0f, fmax(fabs(sp.x.x), fmax(fabs(sp.x.y), fabs(sp.x.z))));
	sp.prim = hit.prim;
	sp.object = s.object;
	sp.emitter = s.emitter;
	sp.material = s.material;
	if (!sp.entering && (sc->materials[s.material].flags & MATERIAL_INTERIOR))
		sp.material++;   /* the inner side: the object's interior_texture */
	sp.m = &sc->materials[sp.material];
	/* the normal's pattern tilts the shading normal (a mesh's own textures'
	 * normals are not applied yet: lower_texture.c says so) */
	if (sp.m->normal >= 0 && !(sp.m->flags & (MATERIAL_LOCAL | MATERIAL_TEXTURE_MAP)))
		sp.ns = texture_normal(sc, sp.m->normal, sp.x, sp.uv, sp.ns);
	return sp;
}

/* Makes material the one shaded at sp: a texture of a pattern of textures, or
 * a layer; its normal pattern tilts the shading normal anew (each texture and
 * layer has its own in POV-Ray). */
static inline void texture_use(const scene_data *sc, shading_point *sp, int material)
{
	sp->m = &sc->materials[material];
	sp->ns = sp->n0;
	if (sp->m->normal >= 0 && !(sp->m->flags & MATERIAL_LOCAL))
		sp->ns = texture_normal(sc, sp->m->normal, sp->x, sp->uv, sp->ns);
}

/* The point a pattern's rows map: p, or the surface's <u, v, 0> for a
 * uv_mapped one. */
static inline float3 texture_at(global const dev_pattern *pt, float3 p, float2 uv)
{
	return pt->flags & PATTERN_UV ? (float3)(uv, 0.0f) : p;
}

/* A point of world space (or of the mesh's, for a mesh's own textures) in a
 * pattern's space: its rows. */
static inline float3 texture_pattern_point(global const dev_pattern *pt, float3 p)
{
	return (float3)(dot(pt->rows[0].xyz, p) + pt->rows[0].w, dot(pt->rows[1].xyz, p) + pt->rows[1].w,
	                dot(pt->rows[2].xyz, p) + pt->rows[2].w);
}

/* An image_map pt at p (its space, warped): the texel or POV-Ray's
 * interpolation of four (kernels/image.cl), then filter all and transmit all.
 * Off a once image: clear (white, transmit 1). */
static inline pigment_colour texture_image(const scene_data *sc, global const dev_pattern *pt, float3 p)
{
	pigment_colour out = { (float3)(1.0f), 0.0f, 1.0f };
	float x, y;
	if (!image_pos(sc, pt, p, &x, &y))
		return out;
	float4 c = image_at(sc, pt, x, y);
	out.rgb = c.xyz;
	out.filter = pt->params[1].x;
	if (sc->images[(int)pt->params[0].x].flags & IMAGE_FILTER)   /* a palette's filters */
		out.filter += image_at_plane(sc, pt, x, y, 1).x;
	out.transmit = 1.0f - c.w + pt->params[1].y;
	return out;
}

/* The value of a pattern that reads an image (image_pattern, density_file)
 * at t (warped), frequency, phase and wave after it, as POV-Ray's Evaluate_TPat. */
static inline float texture_image_value(const scene_data *sc, global const dev_pattern *pt, float3 t)
{
	return pattern_wave(pt, pt->kind == PATTERN_DENSITY_FILE ? density_file_value(sc, pt, t) : image_value(sc, pt, t));
}

/* A pattern's value at q (its space, before its warps): pattern_value, or
 * that of one that reads an image. */
static inline float texture_value(const scene_data *sc, global const dev_pattern *pt, float3 q, float3 n, float3 d)
{
	if (pt->kind == PATTERN_IMAGE_PATTERN || pt->kind == PATTERN_DENSITY_FILE)
		return texture_image_value(sc, pt, pattern_warp_point(pt, sc->warps, q));
	if (pt->kind == PATTERN_MATERIAL_MAP)   /* the number of a map entry */
		return image_material(sc, pt, pattern_warp_point(pt, sc->warps, q));
	return pattern_value(sc, pt, q, n, d);
}

/* pattern_perturb, or the tilt of a pattern that reads an image: a
 * bump_map's, or an image_pattern's or density_file's slope at POV-Ray's
 * pyramid of points (pattern_perturb's for every pattern without a normal of
 * its own). */
static inline float3 texture_perturb(const scene_data *sc, global const dev_pattern *pt, float3 x, float3 n)
{
	if (pt->kind != PATTERN_BUMP_MAP && pt->kind != PATTERN_IMAGE_PATTERN && pt->kind != PATTERN_DENSITY_FILE)
		return pattern_perturb(sc, pt, x, n);
	float3 v = normal_warp_in(pt, sc->warps, n);
	float3 t = pattern_warp_point(pt, sc->warps, texture_pattern_point(pt, x));
	if (pt->kind == PATTERN_BUMP_MAP)
		return normal_warp_out(pt, sc->warps, image_bump(sc, pt, t, v));
	float accuracy = pt->normal.x, k = pt->bump_size * -5.0f * (0.02f / accuracy);
	for (int i = 0; i < 4; i++) {
		float3 dir = normal_pyramid[i].xyz;
		float val = texture_image_value(sc, pt, t + accuracy * dir);
		v += k * normal_slope_map(sc->maps + pt->map_first, pt->map_count, val) * dir;
	}
	return normal_warp_out(pt, sc->warps, v);
}

/* POV-Ray's blend map search: the entries around v, and how far v is from the
 * first to the second (Search_Blend_Map: past the last entry, the last; at or
 * before the first, the first; an entry's own value gives that entry). */
static inline int texture_map_search(global const dev_map_entry *e, int n, float v, int *next, float *frac)
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

/* The sum of the average pattern's weights, its entries' values (never 0:
 * POV-Ray divides by it; eclat gives no colour instead of NaNs). */
static inline float texture_map_weights(global const dev_map_entry *e, int n)
{
	float total = 0.0f;
	for (int i = 0; i < n; i++)
		total += e[i].value;
	return total != 0.0f ? total : INFINITY;
}

/* The point a nested map entry's rows map, its parent pt being at p (the
 * parent's own point, before its rows): p itself, or for a PATTERN_IN_PARENT
 * child the parent's point after its rows and warps. */
static inline float3 texture_child_point(const scene_data *sc, global const dev_pattern *pt, int child, float3 p,
                                         float2 uv)
{
	if (!(sc->patterns[child].flags & PATTERN_IN_PARENT))
		return p;
	return pattern_warp_point(pt, sc->warps, texture_pattern_point(pt, texture_at(pt, p, uv)));
}

/* The pigment whose pattern is root at p (world space: each pattern's rows
 * take it into its own), its map at the pattern's value there, nested
 * pigments evaluated and blended in turn; VALUE(sc, pt, q, n, d) is a
 * pattern's value at q, its point. Made twice, since OpenCL C has no
 * recursion: texture_pigment_tree for surfaces, and function_pigment_tree,
 * which runs no function pattern, for the scene's functions that call a
 * pigment function (function_pattern.cl). */
/* A normal map's entry child of pt perturbing n at x: placed by every
 * transformation around it, or (PATTERN_IN_PARENT) at pt's warped point with
 * n taken into pt's space and back, as POV-Ray's Perturb_Normal does. */
static float3 texture_normal_entry(const scene_data *sc, global const dev_pattern *pt, int child, float3 x, float2 uv,
                                   float3 n)
{
	global const dev_pattern *c = &sc->patterns[child];
	if (!(c->flags & PATTERN_IN_PARENT))
		return texture_perturb(sc, c, texture_at(c, x, uv), n);
	float3 t = texture_child_point(sc, pt, child, x, uv);
	return normal_warp_out(pt, sc->warps, texture_perturb(sc, c, texture_at(c, t, uv), normal_warp_in(pt, sc->warps, n)));
}

/* The unit normal n (facing the ray) perturbed at x by the normal pattern
 * normal. A normal of normals (PATTERN_NORMAL_MAP) perturbs n by the one or
 * two entries its pattern's value picks and blends the results by weight, or
 * (average) by every entry: POV-Ray's Perturb_Normal and Do_Average_Normals,
 * one level deep; each entry's normal is placed by every transformation around
 * it, as nested pigments are. */
static float3 texture_normal(const scene_data *sc, int normal, float3 x, float2 uv, float3 n)
{
	global const dev_pattern *pt = &sc->patterns[normal];
	if (!(pt->flags & PATTERN_NORMAL_MAP))
		return texture_perturb(sc, pt, texture_at(pt, x, uv), n);
	global const dev_map_entry *e = sc->maps + pt->map_first;
	float3 sum = (float3)(0.0f);
	if (pt->kind == PATTERN_AVERAGE) {
		float total = texture_map_weights(e, pt->map_count);
		for (int i = 0; i < pt->map_count; i++) {
			float3 ni = e[i].pigment >= 0 ? texture_normal_entry(sc, pt, e[i].pigment, x, uv, n) : n;
			sum += e[i].value / total * ni;
		}
		return length(sum) > 0.0f ? normalize(sum) : n;
	}
	float v = texture_value(sc, pt, texture_pattern_point(pt, texture_at(pt, x, uv)), n, -n);
	int b;
	float f;
	int a = texture_map_search(e, pt->map_count, v, &b, &f);
	int idx[2] = { a, b };
	float wt[2] = { a == b ? 1.0f : 1.0f - f, a == b ? 0.0f : f };
	for (int k = 0; k < 2; k++) {
		if (wt[k] <= 0.0f)
			continue;
		int child = e[idx[k]].pigment;
		sum += wt[k] * (child >= 0 ? texture_normal_entry(sc, pt, child, x, uv, n) : n);
	}
	return length(sum) > 0.0f ? normalize(sum) : n;
}

/* A camera's normal { } turns each camera ray's direction as a surface's
 * turns its normal, at POV-Ray's image point of the ray (camera_ray's xy, z
 * 0): its TracePixel::CreateCameraRay, after the focal blur. */
static inline float3 camera_perturb(const scene_data *sc, float2 xy, float3 d)
{
	int normal = sc->p->camera_normal;
	if (normal < 0)
		return d;
	return normalize(texture_normal(sc, normal, (float3)(xy, 0.0f), (float2)(0.0f), normalize(d)));
}

#define TEXTURE_STACK 8   /* nested pigments waiting; lower.c keeps maps shallower */

#define TEXTURE_PIGMENT_TREE(NAME, VALUE) \
static pigment_colour NAME(const scene_data *sc, int root, float3 p, float2 uv, float3 n, float3 d) \
{ \
	int stack[TEXTURE_STACK]; \
	float weight[TEXTURE_STACK]; \
	float3 at[TEXTURE_STACK];   /* the point each waiting pigment starts from */ \
	int top = 0; \
	stack[top] = root; \
	at[top] = p; \
	weight[top++] = 1.0f; \
	float4 sum = (float4)(0.0f); \
	float transmit = 0.0f; \
	while (top > 0) { \
		top--; \
		global const dev_pattern *pt = &sc->patterns[stack[top]]; \
		float w = weight[top], v = 0.0f; \
		float3 pp = at[top]; \
		if (pt->kind == PATTERN_AVERAGE) {   /* every entry, by its weight (POV-Ray's ComputeAverage) */ \
			global const dev_map_entry *e = sc->maps + pt->map_first; \
			float total = texture_map_weights(e, pt->map_count); \
			for (int i = 0; i < pt->map_count; i++) { \
				float wi = w * e[i].value / total; \
				if (e[i].pigment >= 0 && top < TEXTURE_STACK) { \
					stack[top] = e[i].pigment; \
					at[top] = texture_child_point(sc, pt, e[i].pigment, pp, uv); \
					weight[top++] = wi; \
				} else { \
					sum += wi * e[i].colour; \
					transmit += wi * e[i].transmit; \
				} \
			} \
			continue; \
		} \
		if (pt->kind != PATTERN_SOLID) { \
			float3 q = texture_pattern_point(pt, texture_at(pt, pp, uv)); \
			if (pt->kind == PATTERN_IMAGE_MAP) {   /* a colour of its own, no map */ \
				pigment_colour c = texture_image(sc, pt, pattern_warp_point(pt, sc->warps, q)); \
				sum += w * (float4)(c.rgb, c.filter); \
				transmit += w * c.transmit; \
				continue; \
			} \
			v = VALUE(sc, pt, q, n, d); \
		} \
		global const dev_map_entry *e = sc->maps + pt->map_first; \
		int b; \
		float f; \
		int a = texture_map_search(e, pt->map_count, v, &b, &f); \
		int idx[2] = { a, b }; \
		float wt[2] = { a == b ? 1.0f : 1.0f - f, a == b ? 0.0f : f }; \
		for (int k = 0; k < 2; k++) { \
			if (wt[k] <= 0.0f) \
				continue; \
			global const dev_map_entry *x = &e[idx[k]]; \
			if (x->pigment >= 0 && top < TEXTURE_STACK) { \
				stack[top] = x->pigment; \
				at[top] = texture_child_point(sc, pt, x->pigment, pp, uv); \
				weight[top++] = w * wt[k]; \
			} else { \
				sum += w * wt[k] * x->colour; \
				transmit += w * wt[k] * x->transmit; \
			} \
		} \
	} \
	pigment_colour out = { sum.xyz, sum.w, transmit }; \
	return out; \
}

TEXTURE_PIGMENT_TREE(texture_pigment_tree, texture_value)

/* The pigment at the shading point: the solid colour, or its pattern's tree. */
static inline pigment_colour texture_pigment(const scene_data *sc, const shading_point *sp)
{
	global const dev_material *m = sp->m;
	pigment_colour out = { m->pigment.xyz, m->pigment.w, m->ambient.w };
	if (m->pattern < 0)
		return out;
	float3 p = m->flags & MATERIAL_LOCAL ? sp->object_x : sp->x;
	return texture_pigment_tree(sc, m->pattern, p, sp->uv, sp->ns, sp->d);
}

/* ---- patterns of whole textures, and layers ---- */

#define TEXTURE_BLEND 8   /* textures blended at a point: 2^TEXTURE_NEST_MAX (lower_texture.c) */

/* The textures that material (a pattern of textures, maybe nested) gives at
 * sp, with their weights, which add up to 1: POV-Ray's Search_Blend_Map picks
 * one entry or blends two at each level. A material that is no pattern of
 * textures is itself, weight 1. */
typedef struct {
	int m[TEXTURE_BLEND];
	float w[TEXTURE_BLEND];
	int n;
} texture_blend;

/* A blob's textures at sp (MATERIAL_BLOB) onto the stack: each component's
 * texture weighted by the size of its field there over their sum, as POV-Ray's
 * Determine_Textures weighs them, but for the weights under adc_bailout,
 * which its ComputeTextureColour skips; the weights of one texture (the
 * components without one of their own show the blob's) added up. Returns how
 * many. */
static inline int texture_blob(const scene_data *sc, const shading_point *sp, global const dev_material *m, int *stack,
                               float *weight)
{
	global const dev_pattern *pt = &sc->patterns[m->pattern];
	global const dev_map_entry *e = sc->maps + pt->map_first;
	global const dev_prim *p = &sc->prims[sp->prim];
	int parts = pt->map_count - 1;
	stack[0] = e[parts].material;   /* the blob's own */
	weight[0] = 1.0f;
	if (p->type != PRIM_BLOB)
		return 1;
	real3 v = intersect_to_local_real(p, sp->x), g = (real3)(0);
	real sum = 0;
	for (int j = 0; j < parts; j++)
		sum += fabs(blob_component_field(sc->prims, p->link + 1 + 2 * j, v, &g));
	if (!(sum > (real)0))   /* no component reaches the point: POV-Ray shows nothing; the blob's own */
		return 1;
	int n = 0;
	for (int j = 0; j < parts; j++) {
		float w = (float)(fabs(blob_component_field(sc->prims, p->link + 1 + 2 * j, v, &g)) / sum);
		if (!(w > 0.0f) || w < sc->p->classic.w)
			continue;
		int k = 0;
		while (k < n && stack[k] != e[j].material)
			k++;
		if (k < n) {
			weight[k] += w;
		} else if (n < TEXTURE_BLEND) {
			stack[n] = e[j].material;
			weight[n++] = w;
		}
	}
	return n > 0 ? n : 1;
}

static inline texture_blend texture_blend_at(const scene_data *sc, const shading_point *sp, int material)
{
	texture_blend b;
	b.n = 0;
	int stack[TEXTURE_BLEND];
	float weight[TEXTURE_BLEND];
	int n = 0;
	if (sc->materials[material].flags & MATERIAL_BLOB) {
		n = texture_blob(sc, sp, &sc->materials[material], stack, weight);
	} else {
		stack[n] = material;
		weight[n++] = 1.0f;
	}
	while (n > 0) {
		n--;
		int mi = stack[n];
		float w = weight[n];
		global const dev_material *m = &sc->materials[mi];
		if (!(m->flags & MATERIAL_TEXTURE_MAP)) {
			if (b.n < TEXTURE_BLEND) {
				b.m[b.n] = mi;
				b.w[b.n++] = w;
			}
			continue;
		}
		global const dev_pattern *pt = &sc->patterns[m->pattern];
		global const dev_map_entry *e = sc->maps + pt->map_first;
		if (pt->kind == PATTERN_AVERAGE) {   /* every texture, by its weight */
			float total = texture_map_weights(e, pt->map_count);
			for (int i = 0; i < pt->map_count && n < TEXTURE_BLEND; i++) {
				stack[n] = e[i].material;
				weight[n++] = w * e[i].value / total;
			}
			continue;
		}
		float3 q = texture_pattern_point(pt, texture_at(pt, m->flags & MATERIAL_LOCAL ? sp->object_x : sp->x, sp->uv));
		float v = texture_value(sc, pt, q, sp->n0, sp->d);
		int c;
		float f;
		int a = texture_map_search(e, pt->map_count, v, &c, &f);
		if (a == c || f <= 0.0f) {
			stack[n] = e[a].material;
			weight[n++] = w;
		} else if (f >= 1.0f) {
			stack[n] = e[c].material;
			weight[n++] = w;
		} else if (n + 2 <= TEXTURE_BLEND) {
			stack[n] = e[a].material;
			weight[n++] = w * (1.0f - f);
			stack[n] = e[c].material;
			weight[n++] = w * f;
		}
	}
	return b;
}

/* What of the light a surface lets through at sp (POV-Ray's shadow rays):
 * over a texture's layers, the product of each one's pigment * filter +
 * transmit; over blended textures, the weighted sum. *pass: the same of
 * |filter| + |transmit|, which says whether anything passes at all. */
static inline float3 texture_filter(const scene_data *sc, shading_point *sp, float *pass)
{
	texture_blend b = texture_blend_at(sc, sp, sp->material);
	float3 sum = (float3)(0.0f);
	*pass = 0.0f;
	for (int k = 0; k < b.n; k++) {
		float3 f = (float3)(1.0f);
		float through = 1.0f;
		for (int mi = b.m[k]; mi >= 0; mi = sp->m->below) {
			sp->m = &sc->materials[mi];
			pigment_colour c = texture_pigment(sc, sp);
			f *= c.rgb * c.filter + c.transmit;
			through *= fabs(c.filter) + fabs(c.transmit);
			/* POV-Ray's fake caustics: the path tracer finds real ones */
			if (sp->m->irid_wavelength.w != 0.0f && sc->p->integrator == INTEGRATOR_WHITTED) {
				texture_use(sc, sp, mi);
				f *= finish_caustics(sp->m, sp->ns, sp->d);
			}
		}
		sum += b.w[k] * f;
		*pass += b.w[k] * through;
	}
	return sum;
}

/* The light a surface emits at sp, as the path tracer sees it on average
 * (texture_choose): over blended textures, the weighted sum; over layers,
 * each layer's pigment * emission, times its opacity unless it is the bottom
 * one, seen through the layers above it. */
static inline float3 texture_emitted(const scene_data *sc, shading_point *sp)
{
	texture_blend b = texture_blend_at(sc, sp, sp->material);
	float3 sum = (float3)(0.0f);
	for (int k = 0; k < b.n; k++) {
		float3 through = (float3)(1.0f);
		for (int mi = b.m[k]; mi >= 0; mi = sp->m->below) {
			sp->m = &sc->materials[mi];
			pigment_colour c = texture_pigment(sc, sp);
			float a = sp->m->below < 0 ? 1.0f : clamp(1.0f - c.filter - c.transmit, 0.0f, 1.0f);
			sum += b.w[k] * through * a * c.rgb * sp->m->emission.xyz;
			through *= c.rgb * c.filter + c.transmit;
		}
	}
	return sum;
}

/* The path tracer's texture at sp, chosen with the uniform number u: one of
 * the blended textures with the probability of its weight, then, down its
 * layers, each layer but the bottom one with the probability of its opacity
 * (1 - filter - transmit), made opaque; passing a layer multiplies *tint by
 * its pigment * filter + transmit over the probability of passing it. In
 * expectation that is POV-Ray's blend of textures and its layers seen through
 * the ones above. Makes the chosen material sp's (texture_use); returns its
 * pigment there. */
static inline pigment_colour texture_choose(const scene_data *sc, shading_point *sp, float u, float3 *tint)
{
	texture_blend b = texture_blend_at(sc, sp, sp->material);
	int mi = b.m[b.n - 1];
	for (int k = 0; k < b.n; k++) {
		if (u < b.w[k]) {
			mi = b.m[k];
			u = fmin(u / b.w[k], 0.99999994f);
			break;
		}
		u -= b.w[k];
	}
	for (;;) {
		texture_use(sc, sp, mi);
		pigment_colour c = texture_pigment(sc, sp);
		if (sp->m->below < 0)
			return c;
		float a = clamp(1.0f - c.filter - c.transmit, 0.0f, 1.0f);
		if (u < a) {
			c.filter = c.transmit = 0.0f;
			return c;
		}
		u = clamp((u - a) / (1.0f - a), 0.0f, 0.99999994f);
		*tint *= (c.rgb * c.filter + c.transmit) / (1.0f - a);
		mi = sp->m->below;
	}
}

/* What a ray that leaves the scene sees: the sky_sphere's pigments at the
 * point of the unit sphere the ray points to, the last written on top, each
 * showing what is below through its filter and transmit, and the background
 * below them all (POV-Ray 3.7's sky, with its emission in the layers'). */
static inline float3 texture_sky(const scene_data *sc, float3 d, bool alpha_ray)
{
	global const dev_params *p = sc->p;
	float3 col = (float3)(0.0f), through = (float3)(1.0f);
	shading_point sp;
	sp.x = sp.object_x = d;
	sp.uv = (float2)(0.0f);
	sp.ng = sp.ns = -d;
	sp.d = d;
	/* POV-Ray 3.6's: a layer's opacity scaled by the filters and transmits
	 * (not the colours) of the layers above it, the background by their
	 * colours' product times their filters' plus their transmits' */
	bool legacy = (p->scene_flags & SCENE_SKY_LEGACY) != 0;
	float3 colours = (float3)(1.0f), emission = (float3)(1.0f);
	float filters = 1.0f, transmits = 1.0f, trans = 1.0f;
	for (int i = p->sky + p->sky_layers - 1; p->sky >= 0 && i >= p->sky; i--) {
		sp.m = &sc->materials[i];
		pigment_colour c = texture_pigment(sc, &sp);
		float opacity = 1.0f - c.filter - c.transmit;
		emission = sp.m->emission.xyz;
		col += c.rgb * (legacy ? trans * opacity : opacity) * (legacy ? emission : through * emission);
		through *= c.filter * c.rgb + c.transmit;
		colours *= c.rgb;
		filters *= c.filter;
		transmits *= c.transmit;
		trans = fabs(filters) + fabs(transmits);
	}
	/* under +UA, rays that show the background as transparent (all but
	 * reflected ones, as in POV-Ray) see its colour times its opacity */
	float opacity = alpha_ray ? 1.0f - p->classic.x : 1.0f;
	if (legacy && p->sky >= 0)
		return col + p->background.xyz * opacity * (colours * filters + transmits);
	return col + p->background.xyz * opacity * through;
}

/* How much of the image's background shows through the sky in direction d,
 * for the alpha channel: POV-Ray's transmittance of the sky's layers times
 * the background's own (dev_params.background.w, 0 without an alpha channel). */
static inline float texture_sky_transm(const scene_data *sc, float3 d)
{
	global const dev_params *p = sc->p;
	if (p->background.w <= 0.0f)
		return 0.0f;
	float3 through = (float3)(1.0f);
	shading_point sp;
	sp.x = sp.object_x = d;
	sp.uv = (float2)(0.0f);
	sp.ng = sp.ns = -d;
	sp.d = d;
	for (int i = p->sky + p->sky_layers - 1; p->sky >= 0 && i >= p->sky; i--) {
		sp.m = &sc->materials[i];
		pigment_colour c = texture_pigment(sc, &sp);
		through *= c.filter * c.rgb + c.transmit;
	}
	return fmin(1.0f, fabs(0.297f * through.x + 0.589f * through.y + 0.114f * through.z)) * p->background.w;
}

static inline void texture_first_hit(first_hit *first, const shading_point *sp, float3 albedo)
{
	if (first->object >= 0)
		return;
	first->albedo = albedo;
	first->normal = sp->ns;
	first->depth = sp->t;
	first->object = sp->object;
}
