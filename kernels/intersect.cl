/* intersect.cl: ray/primitive intersection. Both return the distance of the
 * nearest hit in (tmin, tmax), or tmax when there is none. */

/* Moller-Trumbore on the precomputed edges b = v1 - v0, c = v2 - v0. */
inline float intersect_triangle(float3 o, float3 d, global const dev_prim *p, float tmin, float tmax)
{
	float3 e1 = p->b.xyz, e2 = p->c.xyz;
	float3 pv = cross(d, e2);
	float det = dot(e1, pv);
	if (det == 0.0f)
		return tmax;
	float inv = 1.0f / det;
	float3 tv = o - p->a.xyz;
	float u = dot(tv, pv) * inv;
	if (u < 0.0f || u > 1.0f)
		return tmax;
	float3 qv = cross(tv, e1);
	float v = dot(d, qv) * inv;
	if (v < 0.0f || u + v > 1.0f)
		return tmax;
	float t = dot(e2, qv) * inv;
	return t > tmin && t < tmax ? t : tmax;
}

/* d is unit length. The discriminant is computed from the distance between the
 * centre and the ray's closest point, which keeps its precision for small spheres
 * far away (Haines et al., Ray Tracing Gems, ch. 7). */
inline float intersect_sphere(float3 o, float3 d, global const dev_prim *p, float tmin, float tmax)
{
	float3 oc = o - p->a.xyz;
	float r = p->a.w;
	float b = dot(oc, d);
	float3 f = oc - b * d;
	float disc = r * r - dot(f, f);
	if (disc < 0.0f)
		return tmax;
	float s = sqrt(disc);
	float t0 = -b - s, t1 = -b + s;
	if (t0 > tmin && t0 < tmax)
		return t0;
	if (t1 > tmin && t1 < tmax)
		return t1;
	return tmax;
}

inline float intersect_prim(float3 o, float3 d, global const dev_prim *p, float tmin, float tmax)
{
	return p->type == PRIM_SPHERE ? intersect_sphere(o, d, p, tmin, tmax)
	                              : intersect_triangle(o, d, p, tmin, tmax);
}

/* The geometric normal at a point of the primitive, not yet facing the ray. */
inline float3 prim_normal(global const dev_prim *p, float3 at)
{
	if (p->type == PRIM_SPHERE)
		return normalize(at - p->a.xyz);
	return normalize(cross(p->b.xyz, p->c.xyz));
}
