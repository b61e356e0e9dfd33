/* shape_quadric.cl: POV-Ray's quadric (src/shape_quadric.c): the rows a, b, c
 * map world space to its own, where the polynomial
 *   A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J
 * is zero on the surface and negative inside; its records hold (A, B, C, J),
 * (D, E, F, 0), (G, H, I, 0). The quadratic along the ray is solved in double
 * where the device has it: its roots cancel badly near silhouettes in float. */

#ifdef cl_khr_fp64
typedef double quadric_real;
#else
typedef float quadric_real;
#endif

static inline float quadric_intersect(float3 wo, float3 wd, global const dev_prim *prims, global const dev_prim *p,
                               float tmin, float tmax)
{
	float3 fo = intersect_to_local(p, wo), fd = intersect_dir_to_local(p, wd);
	float4 s = prims[p->link].a, m = prims[p->link + 1].a, l = prims[p->link + 2].a;
	quadric_real A = s.x, B = s.y, C = s.z, J = s.w, D = m.x, E = m.y, F = m.z, G = l.x, H = l.y, I = l.z;
	quadric_real ox = fo.x, oy = fo.y, oz = fo.z, dx = fd.x, dy = fd.y, dz = fd.z;
	quadric_real a = dx * (A * dx + D * dy + E * dz) + dy * (B * dy + F * dz) + dz * C * dz;
	quadric_real b = dx * (A * ox + 0.5 * (D * oy + E * oz + G)) + dy * (B * oy + 0.5 * (D * ox + F * oz + H)) +
	                 dz * (C * oz + 0.5 * (E * ox + F * oy + I));
	quadric_real c = ox * (A * ox + D * oy + E * oz + G) + oy * (B * oy + F * oz + H) + oz * (C * oz + I) + J;
	if (a != 0) {
		quadric_real disc = b * b - a * c;
		if (!(disc > 0))
			return tmax;
		quadric_real r = -(b + copysign(sqrt(disc), b));
		float t0 = (float)(r / a), t1 = r != 0 ? (float)(c / r) : t0;
		return intersect_pick(fmin(t0, t1), fmax(t0, t1), tmin, tmax);
	}
	if (b == 0)
		return tmax;
	float t = (float)(-0.5 * c / b);
	return t > tmin && t < tmax ? t : tmax;
}

static inline float3 quadric_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	float4 s = prims[p->link].a, m = prims[p->link + 1].a, l = prims[p->link + 2].a;
	float3 n = (float3)(2.0f * s.x * q.x + m.x * q.y + m.y * q.z + l.x,
	                    m.x * q.x + 2.0f * s.y * q.y + m.z * q.z + l.y,
	                    m.y * q.x + m.z * q.y + 2.0f * s.z * q.z + l.z);
	if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f)
		n = (float3)(1.0f, 0.0f, 0.0f);
	return intersect_normal_to_world(p, n);
}

static inline bool quadric_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	float4 s = prims[p->link].a, m = prims[p->link + 1].a, l = prims[p->link + 2].a;
	float v = q.x * (s.x * q.x + m.x * q.y + m.y * q.z + l.x) + q.y * (s.y * q.y + m.z * q.z + l.y) +
	          q.z * (s.z * q.z + l.z) + s.w;
	return v <= 0.0f;
}
