#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif

/* intersect.cl: ray/primitive intersection. Both return the distance of the
 * nearest hit in (tmin, tmax), or tmax when there is none. */

/* No fused multiply-adds here: OpenCL lets the compiler contract a * b - c * d
 * into fma(a, b, -c * d) (FP_CONTRACT is on by default), which rounds the two
 * products differently, so two triangles sharing an edge would no longer
 * compute its edge function with exactly opposite signs, and whether a product
 * is fused may change with how the code around it is inlined. */
#pragma OPENCL FP_CONTRACT OFF

/* The component k (0, 1, 2) of v. */
inline float intersect_axis(float3 v, int k)
{
	return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

/* Watertight ray/triangle intersection (Woop, Benthin and Wald, JCGT 2013): the
 * corners are sheared into a space where the ray runs along +z, and the edge
 * functions are evaluated there from the corners themselves, so two triangles
 * that share an edge compute the same edge function for it with opposite signs:
 * a ray through the edge, or through a shared corner, hits one of them. */
inline float intersect_triangle(float3 o, float3 d, global const dev_prim *p, float tmin, float tmax)
{
	float3 ad = fabs(d);
	int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
	int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
	float dz = intersect_axis(d, kz);
	if (dz < 0.0f) {   /* keep the winding: swap x and y */
		int k = kx; kx = ky; ky = k;
	}
	float sx = intersect_axis(d, kx) / dz, sy = intersect_axis(d, ky) / dz, sz = 1.0f / dz;
	float3 a = p->a.xyz - o, b = p->b.xyz - o, c = p->c.xyz - o;
	float az = intersect_axis(a, kz), bz = intersect_axis(b, kz), cz = intersect_axis(c, kz);
	float ax = intersect_axis(a, kx) - sx * az, ay = intersect_axis(a, ky) - sy * az;
	float bx = intersect_axis(b, kx) - sx * bz, by = intersect_axis(b, ky) - sy * bz;
	float cx = intersect_axis(c, kx) - sx * cz, cy = intersect_axis(c, ky) - sy * cz;
	float u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
	if (u == 0.0f || v == 0.0f || w == 0.0f) {   /* on an edge: decide in double where there is one */
#ifdef cl_khr_fp64
		u = (float)((double)cx * by - (double)cy * bx);
		v = (float)((double)ax * cy - (double)ay * cx);
		w = (float)((double)bx * ay - (double)by * ax);
#endif
	}
	if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f))
		return tmax;
	float det = u + v + w;
	if (det == 0.0f)
		return tmax;
	float t = (u * sz * az + v * sz * bz + w * sz * cz) / det;
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

/* a.xyz is the unit normal, a.w the distance of the plane from the origin along it. */
inline float intersect_plane(float3 o, float3 d, global const dev_prim *p, float tmin, float tmax)
{
	float dn = dot(p->a.xyz, d);
	if (dn == 0.0f)
		return tmax;
	float t = (p->a.w - dot(p->a.xyz, o)) / dn;
	return t > tmin && t < tmax ? t : tmax;
}

/* A point in the local space of an ellipsoid (the unit sphere's) or of an
 * instance (its mesh's): the rows a, b, c are the map from world space. */
inline float3 intersect_to_local(global const dev_prim *p, float3 x)
{
	return (float3)(dot(p->a.xyz, x) + p->a.w, dot(p->b.xyz, x) + p->b.w, dot(p->c.xyz, x) + p->c.w);
}

inline float intersect_ellipsoid(float3 o, float3 d, global const dev_prim *p, float tmin, float tmax)
{
	float3 oo = intersect_to_local(p, o);
	float3 dd = (float3)(dot(p->a.xyz, d), dot(p->b.xyz, d), dot(p->c.xyz, d));
	float a = dot(dd, dd), b = dot(oo, dd);
	float3 f = oo - (b / a) * dd;   /* as for spheres: the closest point keeps precision */
	float disc = a * (1.0f - dot(f, f));
	if (disc < 0.0f)
		return tmax;
	float s = sqrt(disc);
	float q = b > 0.0f ? -b - s : -b + s;   /* no cancellation (Numerical Recipes) */
	float t0 = q / a, t1 = q != 0.0f ? (dot(oo, oo) - 1.0f) / q : t0;
	float lo = fmin(t0, t1), hi = fmax(t0, t1);
	if (lo > tmin && lo < tmax)
		return lo;
	if (hi > tmin && hi < tmax)
		return hi;
	return tmax;
}

inline float intersect_prim(float3 o, float3 d, global const dev_prim *p, float tmin, float tmax)
{
	switch (p->type) {
	case PRIM_SPHERE: return intersect_sphere(o, d, p, tmin, tmax);
	case PRIM_PLANE: return intersect_plane(o, d, p, tmin, tmax);
	case PRIM_ELLIPSOID: return intersect_ellipsoid(o, d, p, tmin, tmax);
	default: return intersect_triangle(o, d, p, tmin, tmax);
	}
}

/* The geometric normal at a point of the primitive, not yet facing the ray. */
inline float3 prim_normal(global const dev_prim *p, float3 at)
{
	if (p->type == PRIM_SPHERE)
		return normalize(at - p->a.xyz);
	if (p->type == PRIM_PLANE)
		return p->a.xyz;
	if (p->type == PRIM_ELLIPSOID) {   /* the normal maps by the transposed inverse */
		float3 q = intersect_to_local(p, at);
		return normalize(q.x * p->a.xyz + q.y * p->b.xyz + q.z * p->c.xyz);
	}
	return normalize(cross(p->b.xyz - p->a.xyz, p->c.xyz - p->a.xyz));
}

/* A local normal of an ellipsoid or instance in world space: normals map by the
 * transpose of the world-to-local map. */
inline float3 intersect_normal_to_world(global const dev_prim *p, float3 n)
{
	return normalize(n.x * p->a.xyz + n.y * p->b.xyz + n.z * p->c.xyz);
}

/* The surface at a hit: normals in world space (geometric, and shading, which
 * smooth triangles interpolate), and the material and object, which a mesh's
 * triangle may take from its instance. */
typedef struct {
	float3 ng, ns;
	float3 object_x;  /* the hit in its instance's space (a mesh's), else in world space */
	int material, object;
	int emitter;   /* index into the emitter table, or -1 */
} intersect_surface;

/* Barycentric interpolation of a smooth triangle's three normals at x. */
inline float3 intersect_smooth_normal(global const dev_prim *p, global const float4 *n, float3 x)
{
	float3 e1 = p->b.xyz - p->a.xyz, e2 = p->c.xyz - p->a.xyz, w = x - p->a.xyz;
	float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
	float d20 = dot(w, e1), d21 = dot(w, e2), den = d00 * d11 - d01 * d01;
	float v = den != 0.0f ? (d11 * d20 - d01 * d21) / den : 0.0f;
	float u = den != 0.0f ? (d00 * d21 - d01 * d20) / den : 0.0f;
	float3 s = (1.0f - u - v) * n[0].xyz + v * n[1].xyz + u * n[2].xyz;
	return dot(s, s) > 0.0f ? normalize(s) : (float3)(0.0f);
}

inline intersect_surface intersect_surface_at(global const dev_prim *prims, global const float4 *normals,
                                              int prim, int inst, float3 x)
{
	global const dev_prim *p = &prims[prim];
	intersect_surface s = { (float3)(0.0f), (float3)(0.0f), x, p->material, p->object, -1 };
	float3 lx = x;
	if (inst >= 0) {
		global const dev_prim *q = &prims[inst];
		lx = intersect_to_local(q, x);
		if (s.material < 0)
			s.material = q->material;
		s.object = q->object;
	} else if (p->type == PRIM_TRIANGLE || p->type == PRIM_SPHERE) {
		s.emitter = p->link;
	}
	s.object_x = lx;
	s.ng = prim_normal(p, lx);
	s.ns = s.ng;
	if (p->type == PRIM_SMOOTH_TRIANGLE) {
		float3 ns = intersect_smooth_normal(p, normals + 3 * p->link, lx);
		if (dot(ns, ns) > 0.0f)   /* on the geometric normal's side, as the face's winding says */
			s.ns = dot(ns, s.ng) < 0.0f ? -ns : ns;
	}
	if (inst >= 0) {
		s.ng = intersect_normal_to_world(&prims[inst], s.ng);
		s.ns = intersect_normal_to_world(&prims[inst], s.ns);
	}
	return s;
}
