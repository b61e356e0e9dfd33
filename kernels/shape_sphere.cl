/* shape_sphere.cl: spheres, and ellipsoids (spheres under a transform that is
 * not a similarity), kept as the map from world space to the unit sphere. */

/* d is unit length. The discriminant is computed from the distance between the
 * centre and the ray's closest point, which keeps its precision for small spheres
 * far away (Haines et al., Ray Tracing Gems, ch. 7). */
static inline float sphere_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                              float tmin, float tmax)
{
	float3 oc = o - p->a.xyz;
	float r = p->a.w;
	float b = dot(oc, d);
	float3 f = oc - b * d;
	float disc = r * r - dot(f, f);
	if (disc < 0.0f)
		return tmax;
	float s = sqrt(disc);
	return intersect_pick(-b - s, -b + s, tmin, tmax);
}

static inline float3 sphere_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return normalize(x - p->a.xyz);
}

/* POV-Ray's uv of a point q about a sphere's centre in its own space: u the
 * turn from +x toward +z around y, v from the south pole (0) to the north (1). */
static inline float2 sphere_uv_about(float3 q)
{
	float len = length(q);
	if (len == 0.0f)
		return (float2)(0.0f);
	q /= len;
	float v = 0.5f + asin(clamp(q.y, -1.0f, 1.0f)) / M_PI_F, u = 0.0f;
	float xz = q.x * q.x + q.z * q.z;
	if (xz > 1e-10f) {   /* at the poles any u will do: POV-Ray's 0 */
		float theta = q.z == 0.0f ? (q.x > 0.0f ? 0.0f : M_PI_F) : acos(clamp(q.x / sqrt(xz), -1.0f, 1.0f));
		if (q.z < 0.0f)
			theta = 2.0f * M_PI_F - theta;
		u = theta / (2.0f * M_PI_F);
	}
	return (float2)(u, v);
}

static inline float2 sphere_uv(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return sphere_uv_about(x - p->a.xyz);
}

static inline bool sphere_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 v = x - p->a.xyz;
	return dot(v, v) < p->a.w * p->a.w;
}

/* As an emitter (shape.cl's shape_emit_sample and shape_emit_pdf). Seen from
 * outside, a direction uniform in the cone the sphere fills from x, and the
 * point where it meets the sphere (none, rarely, when rounding misses it);
 * from inside (or on it), a point uniform over its area. */
static inline bool sphere_emit_sample(global const dev_prim *prims, global const dev_prim *p, float3 x, float u1,
                                      float u2, float3 *wi, float3 *pos)
{
	if (dot(p->a.xyz - x, p->a.xyz - x) > p->a.w * p->a.w * 1.0001f) {
		float3 axis = p->a.xyz - x;
		float d2 = dot(axis, axis), r = p->a.w;
		float cos_max = sqrt(fmax(0.0f, 1.0f - r * r / d2));
		float cos_t = 1.0f - u1 * (1.0f - cos_max), sin_t = sqrt(fmax(0.0f, 1.0f - cos_t * cos_t));
		float3 t, b, w = axis * rsqrt(d2);
		intersect_basis(w, &t, &b);
		*wi = normalize(sin_t * cos(2.0f * M_PI_F * u2) * t + sin_t * sin(2.0f * M_PI_F * u2) * b + cos_t * w);
		float th = sphere_intersect(x, *wi, prims, p, 0.0f, INFINITY);
		if (th == INFINITY)
			return false;
		*pos = x + th * *wi;
		return true;
	}
	float z = 1.0f - 2.0f * u1, s = sqrt(fmax(0.0f, 1.0f - z * z)), phi = 2.0f * M_PI_F * u2;
	*pos = p->a.xyz + p->a.w * (float3)(s * cos(phi), s * sin(phi), z);
	*wi = normalize(*pos - x);
	return true;
}

/* The density of the point t along wi from x in solid angle, pick times it;
 * area: the sphere's (the emitter table's). */
static inline float sphere_emit_pdf(global const dev_prim *prims, global const dev_prim *p, float3 x, float3 wi,
                                    float t, float pick, float area)
{
	float3 c = p->a.xyz;
	float r = p->a.w, d2 = dot(c - x, c - x);
	if (d2 > r * r * 1.0001f) {
		float cos_max = sqrt(fmax(0.0f, 1.0f - r * r / d2));
		return pick / (2.0f * M_PI_F * (1.0f - cos_max));
	}
	float3 nl = normalize(x + t * wi - c);
	return pick * t * t / (area * fabs(dot(nl, wi)));
}

static inline float ellipsoid_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                                 float tmin, float tmax)
{
	float3 oo = intersect_to_local(p, o), dd = intersect_dir_to_local(p, d);
	float a = dot(dd, dd), b = dot(oo, dd);
	float3 f = oo - (b / a) * dd;   /* as for spheres: the closest point keeps precision */
	float disc = a * (1.0f - dot(f, f));
	if (disc < 0.0f)
		return tmax;
	float s = sqrt(disc);
	float q = b > 0.0f ? -b - s : -b + s;   /* no cancellation (Numerical Recipes) */
	float t0 = q / a, t1 = q != 0.0f ? (dot(oo, oo) - 1.0f) / q : t0;
	return intersect_pick(fmin(t0, t1), fmax(t0, t1), tmin, tmax);
}

/* An ellipsoid's uv is its unit sphere's: the sphere's uv in its own space. */
static inline float2 ellipsoid_uv(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return sphere_uv_about(intersect_to_local(p, x));
}

static inline float3 ellipsoid_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return intersect_normal_to_world(p, intersect_to_local(p, x));
}

static inline bool ellipsoid_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	return dot(q, q) < 1.0f;
}
