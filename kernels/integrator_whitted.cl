/* integrator_whitted.cl: POV-Ray 3.7's classic lighting model, for previews and
 * for pixel-level cross-checks against povray (tests/povray.test).
 *
 * A camera ray's colour (kernels/whitted_pixel.cl makes the rays of a pixel as
 * POV-Ray does, with or without anti-aliasing and focal blur). At each surface,
 * as POV-Ray's Trace::ComputeLightedTexture does for a one-layer texture:
 *   colour = pigment * (ambient * ambient_light + emission) * opacity
 *          + for each light_source: diffuse, phong and specular (whitted_light)
 *          + filter colour * what the refracted ray sees (TIR: its reflection)
 *          + reflectivity * what the reflected ray sees ^ exponent
 * where opacity = 1 - filter - transmit and filter colour = pigment * filter +
 * transmit. Rays stop at max_trace_level (params max_depth) or when their weight
 * falls under adc_bailout; POV-Ray's ray tree is walked with an explicit stack of
 * frames, the reflected and refracted rays being each frame's children.
 * A layered texture is shaded as ComputeLightedTexture shades it: each layer's
 * colour seen through the layers above it, each layer's reflection, one
 * refraction through them all; blended textures of a pattern of textures are
 * each shaded so and their colours mixed by weight (ComputeOneTextureColour).
 * Children along the same ray are traced once, their multipliers added. */

#define WHITTED_FRAMES 24        /* trace levels the kernel follows, at most */
#define WHITTED_CHILDREN 4       /* distinct rays a surface spawns, at most (more are dropped) */
#define WHITTED_REFLECTIONS 4    /* reflecting layers of one texture, at most (more are dropped) */
#define WHITTED_REGIONS 40       /* an area light's grid regions waiting, at most */
#define POV_EPSILON 1e-10f       /* POV-Ray's EPSILON */

/* The kinds of rays, for POV-Ray's no_image and no_reflection and for whether a
 * ray counts a trace level: a ray that only passes through a surface of the same
 * ior (POV-Ray's "continued" ray) does not. */
enum { WRAY_IMAGE = 1, WRAY_REFLECTED = 2, WRAY_CONTINUED = 4 };

typedef struct {
	float3 o, d;
	float3 mult;       /* the parent adds mult * (this ray's colour)^exponent */
	float exponent;
	float weight;      /* POV-Ray's ray weight, against adc_bailout */
	int level;         /* trace level when the ray is traced */
	int kind;          /* WRAY_ */
	int solids;        /* the solid (non-hollow) objects it is in: no fog while there is one */
	media_stack media; /* the interiors with media it is in */
	float alpha;       /* the parent's transmittance gets alpha * this ray's (POV-Ray's
	                    * resultTransm): the transmitted ray's, 0 for the others */
} whitted_ray;

typedef struct {
	whitted_ray ray;
	float3 colour;     /* the ray's colour so far */
	float fog_t;       /* how far the ray goes through fog and rainbows (INFINITY: it leaves
	                    * the scene), or -1 */
	float media_t;     /* how far it goes through its interiors' media, or -1 */
	float transm;      /* how much of the background shows through, for the alpha channel */
	whitted_ray child[WHITTED_CHILDREN];
	int n_child, next;
} whitted_frame;

/* Everything one shading point needs to know. */
typedef struct {
	float3 x;          /* the hit point */
	float3 n;          /* normal, turned to face the ray */
	float3 d;          /* the ray's direction */
	float eps;         /* how far rays start off the surface */
	int object;
	int solids;        /* the solid objects around the point, for fog_shadow */
	media_stack media; /* the interiors with media around it, for its shadow rays */
	float irid_t;      /* irid's film thickness there (finish_irid_thickness) */
} whitted_point;

static inline float whitted_max3(float3 c)
{
	return fmax(c.x, fmax(c.y, c.z));
}

/* POV-Ray's greyscale weights. */
static inline float whitted_grey(float3 c)
{
	return 0.297f * c.x + 0.589f * c.y + 0.114f * c.z;
}

static inline float3 whitted_pow3(float3 c, float e)
{
	return e == 1.0f ? c : pow(c, (float3)(e));
}

/* POV-Ray's empirical Fresnel curve of "metallic": 0 at normal incidence, 1 at
 * grazing; metallic tints by the pigment where it is small. */
static inline float3 whitted_metallic_tint(float metallic, float cos_angle, float3 pigment)
{
	float x = fabs(acos(clamp(cos_angle, -1.0f, 1.0f))) / M_PI_2_F;
	float f = clamp(0.014567225f / ((x - 1.12f) * (x - 1.12f)) - 0.011612903f, 0.0f, 1.0f);
	return (float3)(1.0f) + metallic * (1.0f - f) * (pigment - (float3)(1.0f));
}

/* The position of grid light (u, v) of an area light, and its axes when oriented
 * (TraceAreaLightSubsetShadowRay, without jitter). */
static inline float3 whitted_grid_point(global const dev_light *l, int size1, int size2, int u, int v, float3 a1, float3 a2)
{
	float ju = (float)u, jv = (float)v;
	if (l->axis2.w > 0.0f) {   /* circular */
		ju = ju / (float)(size1 - 1) - 0.5f + 0.001f;
		jv = jv / (float)(size2 - 1) - 0.5f + 0.001f;
		float s = fmax(fabs(ju), fabs(jv)) / sqrt(ju * ju + jv * jv);
		return l->position.xyz + a1 * (ju * s) + a2 * (jv * s);
	}
	float3 p = l->position.xyz;
	if (size1 > 1)
		p += a1 * (ju / (float)(size1 - 1) - 0.5f);
	if (size2 > 1)
		p += a2 * (jv / (float)(size2 - 1) - 0.5f);
	return p;
}

/* A shadow ray: through the media of the interiors it crosses when the scene
 * has any (POV-Ray's shadow rays carry the ray's interiors; area lights' start
 * outside them). */
static inline float3 whitted_shadow_in(const scene_data *sc, media_stack s, float3 x, float3 l, float tmin, float tmax,
                                float3 colour)
{
	if (sc->p->scene_flags & SCENE_MEDIA)
		return media_shadow(sc, s, x, l, tmin, tmax, colour);
	return visibility_shadow(sc, x, l, tmin, tmax, colour);
}

static inline float3 whitted_shadow(const scene_data *sc, float3 x, float3 l, float tmin, float tmax, float3 colour)
{
	return whitted_shadow_in(sc, media_none(), x, l, tmin, tmax, colour);
}

/* The light of one grid point that reaches x. */
static inline float3 whitted_grid_sample(const scene_data *sc, global const dev_light *l, int s1, int s2, int u, int v,
                                  float3 a1, float3 a2, float3 x, float3 colour, float eps, int solids)
{
	float3 to = whitted_grid_point(l, s1, s2, u, v, a1, a2) - x;
	float dist = length(to);
	return dist > 0.0f ? whitted_shadow(sc, x, to / dist, eps, dist - eps, colour) *
	                     fog_shadow(sc, l, x, to / dist, dist, solids) *
	                     media_atmosphere_shadow(sc, l, x, to / dist, dist, solids) : colour;
}

/* An area light's shadow: POV-Ray samples the grid's corners and splits a region
 * in four while its corners differ (or down to the adaptive level), averaging
 * the four quarters; the grid is size1 x size2 lights, unjittered. */
static inline float3 whitted_area_shadow(const scene_data *sc, global const dev_light *l, float3 x, float3 to_light,
                                  float3 colour, float eps, int solids)
{
	int s1 = (int)l->grid.x, s2 = (int)l->grid.y;
	float3 a1 = l->axis1.xyz, a2 = l->axis2.xyz;
	if (l->grid.w > 0.0f) {   /* orient: square, facing the point */
		float len = length(a1);
		float3 t = fabs(fabs(to_light.z) - 1.0f) < 0.01f ? (float3)(0.0f, 1.0f, 0.0f) : (float3)(0.0f, 0.0f, 1.0f);
		a1 = normalize(cross(to_light, t));
		a2 = normalize(cross(to_light, a1)) * len;
		a1 *= len;
	}
	int4 stack[WHITTED_REGIONS];   /* regions of the grid: first and last light on each side */
	int depth[WHITTED_REGIONS];    /* how often the grid was cut to make them */
	int sp = 0;
	float3 sum = (float3)(0.0f);
	stack[sp] = (int4)(0, 0, s1 - 1, s2 - 1);
	depth[sp++] = 0;
	while (sp > 0) {
		sp--;
		int4 r = stack[sp];
		int level = depth[sp];
		float3 c0 = whitted_grid_sample(sc, l, s1, s2, r.x, r.y, a1, a2, x, colour, eps, solids);
		float3 c1 = whitted_grid_sample(sc, l, s1, s2, r.z, r.y, a1, a2, x, colour, eps, solids);
		float3 c2 = whitted_grid_sample(sc, l, s1, s2, r.x, r.w, a1, a2, x, colour, eps, solids);
		float3 c3 = whitted_grid_sample(sc, l, s1, s2, r.z, r.w, a1, a2, x, colour, eps, solids);
		float3 d01 = fabs(c0 - c1), d13 = fabs(c1 - c3), d32 = fabs(c3 - c2), d20 = fabs(c2 - c0);
		bool split = (r.z - r.x > 1 || r.w - r.y > 1) &&
		             (level < (int)l->grid.z || d01.x + d01.y + d01.z > 0.1f || d13.x + d13.y + d13.z > 0.1f ||
		              d32.x + d32.y + d32.z > 0.1f || d20.x + d20.y + d20.z > 0.1f);
		if (!split || sp + 4 > WHITTED_REGIONS) {
			/* a region is the mean of its quarters, so one cut level deep weighs 1/4^level */
			sum += ldexp(0.25f, -2 * level) * (c0 + c1 + c2 + c3);
			continue;
		}
		int mu0 = (r.x + r.z) / 2, mu1 = (r.x + r.z + 1) / 2, mv0 = (r.y + r.w) / 2, mv1 = (r.y + r.w + 1) / 2;
		int4 quarters[4] = { (int4)(r.x, r.y, mu0, mv0), (int4)(mu1, r.y, r.z, mv0), (int4)(r.x, mv1, mu0, r.w),
		                     (int4)(mu1, mv1, r.z, r.w) };
		for (int q = 0; q < 4; q++) {
			stack[sp] = quarters[q];
			depth[sp++] = level + 1;
		}
	}
	return sum;
}

/* POV-Ray's diffuse term: pigment * light * |N.L|^brilliance * diffuse * opacity,
 * less crand's grain (crand * a uniform number, u). */
static inline float3 whitted_diffuse(global const dev_material *f, float3 pigment, float3 n, float3 l, float3 light,
                              float opacity, float u)
{
	float c = fabs(dot(n, l));
	float k = f->terms.x != 1.0f ? pow(c, f->terms.x) : c;
	k *= f->emission.w * opacity;
	if (f->irid.w > 0.0f && f->emission.w > 0.0f)
		k -= u * f->irid.w;
	return k * pigment * light;
}

/* phong: the light direction against the mirror direction of the eye ray,
 * to the power phong_size; metallic tints it by the pigment. */
static inline float3 whitted_phong(global const dev_material *f, float3 pigment, float3 n, float3 d, float3 l, float3 light)
{
	float3 r = d - 2.0f * dot(d, n) * n;
	float c = dot(r, l);
	if (c <= 0.0f || !(f->highlight.y < 60.0f || c > 0.0008f))
		return (float3)(0.0f);
	float k = f->highlight.x * pow(c, f->highlight.y);
	float3 tint = f->terms.y > 0.0f ? whitted_metallic_tint(f->terms.y, dot(n, l), pigment) : (float3)(1.0f);
	return k * light * tint;
}

/* specular: the half vector against the normal, to the power 1/roughness. */
static inline float3 whitted_specular(global const dev_material *f, float3 pigment, float3 n, float3 d, float3 l,
                               float3 light)
{
	float3 h = 0.5f * (l - d);
	float len = length(h);
	if (len <= 0.0f)
		return (float3)(0.0f);
	float c = dot(h, n) / len;
	if (c <= 0.0f)
		return (float3)(0.0f);
	float k = f->highlight.z * pow(c, f->highlight.w);
	float3 tint = f->terms.y > 0.0f ? whitted_metallic_tint(f->terms.y, dot(n, l), pigment) : (float3)(1.0f);
	return k * light * tint;
}

/* The direction to a light, the distance its shadow ray goes, and its colour
 * after fade and spotlight (ComputeOneLightRay). */
static inline float3 whitted_light_ray(global const dev_light *l, float3 x, float3 *dir, float *dist)
{
	float3 to = l->position.xyz - x;
	if (l->kind == LIGHT_KIND_PARALLEL) {
		*dir = -l->spot.xyz;
		*dist = dot(to, *dir);
		return l->color.xyz;
	}
	*dist = length(to);
	*dir = *dist > 0.0f ? to / *dist : (float3)(0.0f, 1.0f, 0.0f);
	float k = light_fade(l, *dist);
	if (l->kind == LIGHT_KIND_SPOT)
		k *= light_spot(l, -*dir);
	return k * l->color.xyz;
}

/* The sum of every light_source's diffuse and highlights at a point (ComputeDiffuseLight). */
static inline float3 whitted_lights(const scene_data *sc, global const dev_material *f, float3 pigment,
                             const whitted_point *pt, float opacity)
{
	float3 sum = (float3)(0.0f);
	bool both_sides = sc->objects[pt->object] & OBJECT_DOUBLE_ILLUMINATE;
	float3 from = pt->x;
	for (int i = 0; i < sc->p->n_lights; i++) {
		global const dev_light *l = &sc->lights[i];
		float3 dir;
		float dist;
		float3 light = whitted_light_ray(l, pt->x, &dir, &dist);
		if (fabs(light.x) < POV_EPSILON && fabs(light.y) < POV_EPSILON && fabs(light.z) < POV_EPSILON)
			continue;
		if (!both_sides && dot(pt->n, dir) < POV_EPSILON)
			continue;
		if (!l->shadowless) {
			if (l->grid.x > 0.0f)
				light = whitted_area_shadow(sc, l, from, dir, light, pt->eps, pt->solids);
			else
				light = whitted_shadow_in(sc, pt->media, from, dir, pt->eps, dist - pt->eps, light) *
				        fog_shadow(sc, l, from, dir, dist, pt->solids) *
				        media_atmosphere_shadow(sc, l, from, dir, dist, pt->solids);
		}
		if (fabs(light.x) <= POV_EPSILON && fabs(light.y) <= POV_EPSILON && fabs(light.z) <= POV_EPSILON)
			continue;
		float u = f->irid.w > 0.0f ? finish_crand_at(pt->x, i, (uint)sc->p->seed) : 0.0f;
		float3 lit = whitted_diffuse(f, pigment, pt->n, dir, light, opacity, u);
		if (!l->shadowless) {   /* POV-Ray's shadowless lights are fill lights: no highlights */
			if (f->highlight.x > 0.0f)
				lit += whitted_phong(f, pigment, pt->n, pt->d, dir, light);
			if (f->highlight.z > 0.0f)
				lit += whitted_specular(f, pigment, pt->n, pt->d, dir, light);
		}
		if (f->irid.x > 0.0f)   /* irid tints each light's diffuse and highlights */
			lit *= finish_irid_tint(f->irid.x, pt->irid_t, f->irid_wavelength.xyz, pt->n, dir, pt->d);
		sum += lit;
	}
	return sum;
}

/* How much the surface reflects at this angle, and the reflected ray's weight
 * (ComputeReflectivity, then reflection's metallic). ior_ratio: the ior on the
 * far side over the near side's. */
static inline float3 whitted_reflectivity(global const dev_material *f, float3 pigment, float cos_i, float ior_ratio,
                                   float *weight)
{
	float3 lo = f->reflection.xyz, hi = f->reflection_max.xyz, r;
	if (f->terms.w > 0.0f) {   /* fresnel */
		float sqx = ior_ratio * ior_ratio + cos_i * cos_i - 1.0f;
		if (sqx > 0.0f) {
			float g = sqrt(sqx);
			float a = (g - cos_i) / (g + cos_i), b = (cos_i * (g + cos_i) - 1.0f) / (cos_i * (g - cos_i) + 1.0f);
			float k = clamp(0.5f * a * a * (1.0f + b * b), 0.0f, 1.0f);
			r = k * hi + (1.0f - k) * lo;
		} else {
			r = hi;
		}
		*weight *= whitted_max3(r);
	} else {
		*weight *= fmax(whitted_max3(hi), whitted_max3(lo));
		float falloff = f->reflection.w;
		float frac = fabs(falloff - 1.0f) > POV_EPSILON ? pow(1.0f - cos_i, falloff) : 1.0f - cos_i;
		r = fabs(frac) < POV_EPSILON ? lo : fabs(frac - 1.0f) < POV_EPSILON ? hi : frac * hi + (1.0f - frac) * lo;
	}
	if (f->terms.z != 0.0f)
		r *= whitted_metallic_tint(f->terms.z, cos_i, pigment);
	return r;
}

static inline whitted_ray whitted_child(float3 o, float3 d, float3 mult, float exponent, float weight, int level, int kind,
                                 int solids, media_stack media)
{
	whitted_ray r = { o, d, mult, exponent, weight, level, kind, solids, media, 0.0f };
	return r;
}

/* Adds a child ray to fr: one along the same ray with the same exponent gets
 * its multiplier added (the parent adds mult * colour^exponent, so they sum). */
static inline void whitted_add_child(whitted_frame *fr, whitted_ray r)
{
	if (r.mult.x == 0.0f && r.mult.y == 0.0f && r.mult.z == 0.0f)
		return;
	for (int i = 0; i < fr->n_child; i++) {
		whitted_ray *c = &fr->child[i];
		if (all(c->o == r.o) && all(c->d == r.d) && c->exponent == r.exponent && c->kind == r.kind &&
		    c->level == r.level && c->solids == r.solids && c->media.n == r.media.n &&
		    (r.media.n == 0 || c->media.first[r.media.n - 1] == r.media.first[r.media.n - 1])) {
			c->mult += r.mult;
			c->alpha += r.alpha;
			c->weight = fmax(c->weight, r.weight);
			return;
		}
	}
	if (fr->n_child < WHITTED_CHILDREN)
		fr->child[fr->n_child++] = r;
}

/* One texture (a top layer and the layers below it) at sp, its colour and
 * children added to fr with weight w: POV-Ray's ComputeLightedTexture. Each
 * layer adds its own colour (ambient, diffuse with its opacity, highlights)
 * seen through the layers above (filcol), and its reflection; the layers stop
 * where too little shows through (adc_bailout); the refracted ray goes along
 * the top layer's normal through all of them. */
static inline void whitted_texture(const scene_data *sc, whitted_frame *fr, shading_point sp, int material, float w,
                            whitted_ray ray, int level, float t_hit, first_hit *first)
{
	global const dev_params *p = sc->p;
	float3 filcol = (float3)(1.0f), top_n = sp.n0;
	float trans = 1.0f;
	float3 refl_n[WHITTED_REFLECTIONS], refl_c[WHITTED_REFLECTIONS];
	float refl_w[WHITTED_REFLECTIONS], refl_e[WHITTED_REFLECTIONS];
	int n_refl = 0;
	bool entering = sp.entering;
	float ior = 1.0f;
	whitted_point pt;
	pt.d = ray.d;
	pt.x = sp.x;
	pt.eps = sp.eps;
	pt.object = sp.object;
	pt.solids = ray.solids;
	pt.media = ray.media;
	for (int mi = material, layer = 0; mi >= 0 && trans > p->classic.w; mi = sp.m->below, layer++) {
		texture_use(sc, &sp, mi);
		pigment_colour pc = texture_pigment(sc, &sp);
		global const dev_material *f = sp.m;
		if (layer == 0) {
			top_n = sp.ns;
			ior = f->interior.x;
			texture_first_hit(first, &sp, pc.rgb);
		}
		pt.n = sp.ns;
		pt.irid_t = f->irid.x > 0.0f ? finish_irid_thickness(f, pt.x) : 0.0f;
		float3 pig = pc.rgb;
		float cos_i = -dot(ray.d, pt.n);
		float rweight = ray.weight * trans;
		float3 reflec = whitted_reflectivity(f, pig, cos_i, entering ? ior : 1.0f / ior, &rweight);
		float opacity = 1.0f - pc.filter - pc.transmit;
		fr->colour += w * filcol *
		              (pig * (f->ambient.xyz + f->emission.xyz) * opacity + whitted_lights(sc, f, pig, &pt, opacity));
		if ((reflec.x != 0.0f || reflec.y != 0.0f || reflec.z != 0.0f) && n_refl < WHITTED_REFLECTIONS) {
			refl_n[n_refl] = pt.n;
			if (f->irid.x > 0.0f) {   /* irid tints the reflected colour before its exponent */
				float3 r = ray.d - 2.0f * dot(ray.d, pt.n) * pt.n;
				reflec *= whitted_pow3(finish_irid_tint(f->irid.x, pt.irid_t, f->irid_wavelength.xyz, pt.n, r, ray.d),
				                       f->reflection_max.w);
			}
			refl_c[n_refl] = reflec;
			refl_w[n_refl] = rweight;
			refl_e[n_refl++] = f->reflection_max.w;
		}
		filcol *= pig * pc.filter + pc.transmit;
		if (f->interior.w > 0.0f)   /* conserve_energy: what is reflected is not transmitted */
			filcol *= fmin((float3)(1.0f), (float3)(1.0f) - reflec);
		trans = fmin(1.0f, fabs(whitted_grey(filcol)));
	}
	bool tir = false;
	int image = ray.kind & WRAY_IMAGE;
	float cos_i = -dot(ray.d, top_n);
	float3 ng = sp.ng;
	/* through the surface, the ray enters or leaves the object (POV-Ray's
	 * interior list, reduced to a count of the solid ones) */
	int through = ray.solids;
	if (!(sc->objects[sp.object] & OBJECT_HOLLOW))
		through = entering ? through + 1 : max(through - 1, 0);
	media_stack inside = media_cross(ray.media, &sc->materials[material]);
	if (trans > p->classic.w) {
		float tweight = ray.weight * whitted_max3(fabs(filcol));
		float3 att = entering ? (float3)(1.0f) : visibility_fade(sp.m, t_hit);
		float ratio = entering ? 1.0f / ior : ior;
		float3 below = sp.x - sp.eps * ng;
		float alpha = w * whitted_grey(att) * trans;   /* the background seen through */
		if (fabs(ratio - 1.0f) < POV_EPSILON) {
			whitted_ray c = whitted_child(below, ray.d, w * att * filcol, 1.0f, tweight, level,
			                              image | WRAY_CONTINUED | (ray.kind & WRAY_REFLECTED), through, inside);
			c.alpha = alpha;
			whitted_add_child(fr, c);
		} else {
			float t = 1.0f + ratio * ratio * (cos_i * cos_i - 1.0f);
			if (t < 0.0f) {   /* total internal reflection, unfiltered */
				tir = true;
				float3 r = ray.d + 2.0f * cos_i * top_n;
				whitted_add_child(fr, whitted_child(sp.x + sp.eps * ng, normalize(r), w * att, 1.0f, tweight, level,
				                                    WRAY_REFLECTED, ray.solids, ray.media));
			} else {
				float3 dir = ratio * ray.d + (ratio * cos_i - sqrt(t)) * top_n;
				whitted_ray c = whitted_child(below, normalize(dir), w * att * filcol, 1.0f, tweight, level,
				                              image | (ray.kind & WRAY_REFLECTED), through, inside);
				c.alpha = alpha;
				whitted_add_child(fr, c);
			}
		}
	}
	for (int i = 0; i < n_refl; i++) {
		if (tir && all(refl_n[i] == top_n))   /* TIR reflects along the top normal already */
			continue;
		float3 r = ray.d - 2.0f * dot(ray.d, refl_n[i]) * refl_n[i];
		whitted_add_child(fr, whitted_child(sp.x + sp.eps * ng, normalize(r), w * refl_c[i], refl_e[i], refl_w[i],
		                                    level, WRAY_REFLECTED, ray.solids, ray.media));
	}
}

/* Traces one ray: its surface's own colour, and the rays it spawns as children. */
static inline whitted_frame whitted_shade(const scene_data *sc, whitted_ray ray, float tmax, first_hit *first)
{
	whitted_frame fr;
	fr.ray = ray;
	fr.colour = (float3)(0.0f);
	fr.fog_t = -1.0f;
	fr.media_t = -1.0f;
	fr.transm = 0.0f;
	fr.n_child = fr.next = 0;
	global const dev_params *p = sc->p;
	if (ray.level >= p->max_depth || ray.weight < p->classic.w)
		return fr;   /* black, and unfogged, as POV-Ray's TraceRay returns early */
	int skip = ray.kind & WRAY_REFLECTED ? OBJECT_NO_REFLECTION : OBJECT_NO_IMAGE;
	int kind = ray.level == 0 ? RAY_CAMERA : RAY_BOUNCE;
	traverse_hit hit = visibility_closest(sc, ray.o, ray.d, 0.0f, tmax, skip, kind);
	if (ray.solids == 0 && (p->n_fogs > 0 || p->n_atmosphere > 0 || p->n_rainbows > 0))
		fr.fog_t = hit.prim < 0 ? INFINITY : hit.t;
	if (ray.solids == 0 && ray.media.n > 0 && hit.prim >= 0)
		fr.media_t = hit.t;
	if (hit.prim < 0) {
		bool alpha_ray = !(ray.kind & WRAY_REFLECTED);
		fr.colour = texture_sky(sc, ray.d, alpha_ray);
		fr.transm = alpha_ray ? texture_sky_transm(sc, ray.d) : 0.0f;
		return fr;
	}
	int level = ray.level + (ray.kind & WRAY_CONTINUED ? 0 : 1);
	shading_point sp = texture_point(sc, hit, ray.o, ray.d);
	texture_blend b = texture_blend_at(sc, &sp, sp.material);
	for (int k = 0; k < b.n; k++)
		whitted_texture(sc, &fr, sp, b.m[k], b.w[k], ray, level, hit.t, first);
	return fr;
}

/* The colour of a camera ray: POV-Ray's recursion, as a walk over a stack of
 * frames; a finished frame adds its colour to its parent's. */
static inline float3 whitted_radiance(const scene_data *sc, whitted_ray camera, first_hit *first, float *transm)
{
	global const dev_params *p = sc->p;
	whitted_frame stack[WHITTED_FRAMES];
	int sp = 0;
	stack[sp++] = whitted_shade(sc, camera, camera_max_distance(sc), first);
	float3 result = (float3)(0.0f);
	while (sp > 0) {
		whitted_frame *top = &stack[sp - 1];
		if (top->next < top->n_child && sp < WHITTED_FRAMES) {
			whitted_ray r = top->child[top->next++];
			sc->counts[COUNT_RAYS + RAY_BOUNCE]++;
			stack[sp++] = whitted_shade(sc, r, INFINITY, first);
			continue;
		}
		float3 c = top->colour;
		whitted_ray r = top->ray;
		if (top->media_t >= 0.0f) {   /* the interiors' media, then the rainbows, the atmosphere's and the fog */
			media_list l = media_gather(&r.media);
			c = media_whitted(sc, &l, r.media, r.o, r.d, top->media_t, c);
		}
		float tr = top->transm;
		if (top->fog_t >= 0.0f && p->n_rainbows > 0) {   /* POV-Ray's order: rainbows, atmosphere, fog */
			uint key = as_uint(r.o.x) ^ rng_hash(as_uint(r.d.y) ^ rng_hash(as_uint(r.d.x) + as_uint(r.o.z)));
			rainbow_effect re = rainbow_segment(sc, r.d, top->fog_t, key);
			c = re.add + re.att * c;
			tr *= re.transm;
		}
		if (top->fog_t >= 0.0f && p->n_atmosphere > 0) {
			media_list l = media_atmosphere(sc);
			c = media_whitted(sc, &l, r.media, r.o, r.d, top->fog_t, c);
		}
		if (top->fog_t >= 0.0f && p->n_fogs > 0) {   /* the fog over the ray, after all it brought back */
			fog_effect fe = fog_segment(sc, r.o, r.d, top->fog_t, false);
			c = fe.add + fe.att * c;
		}
		if (--sp == 0) {
			result = c;
			*transm = tr;
		} else {
			stack[sp - 1].colour += r.mult * whitted_pow3(c, r.exponent);
			stack[sp - 1].transm += r.alpha * tr;
		}
	}
	return result;
}
