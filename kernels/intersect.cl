#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif

/* intersect.cl: what the shapes' kernel files (shape_*.cl) share. Every
 * name_intersect returns the distance of the nearest hit in (tmin, tmax), or
 * tmax when there is none; name_normal the outward geometric normal at a point
 * of the surface, not yet facing the ray; name_inside whether a point is inside
 * the solid (POV-Ray's Inside; shapes with no inside say false). */

/* No fused multiply-adds here: OpenCL lets the compiler contract a * b - c * d
 * into fma(a, b, -c * d) (FP_CONTRACT is on by default), which rounds the two
 * products differently, so two triangles sharing an edge would no longer
 * compute its edge function with exactly opposite signs, and whether a product
 * is fused may change with how the code around it is inlined. */
#pragma OPENCL FP_CONTRACT OFF

/* The precision of the shapes that search for their roots (torus,
 * superellipsoid): double where the device has it, since float loses grazing
 * rays' roots; float elsewhere. */
#ifdef cl_khr_fp64
typedef double real;
typedef double3 real3;
#define convert_real3 convert_double3
#define REAL_EPSILON DBL_EPSILON
#else
typedef float real;
typedef float3 real3;
#define convert_real3 convert_float3
#define REAL_EPSILON FLT_EPSILON
#endif

/* intersect_to_local and intersect_dir_to_local in that precision. */
static inline real3 intersect_to_local_real(global const dev_prim *p, float3 x)
{
	real3 v = convert_real3(x);
	return (real3)(dot(convert_real3(p->a.xyz), v) + p->a.w, dot(convert_real3(p->b.xyz), v) + p->b.w,
	               dot(convert_real3(p->c.xyz), v) + p->c.w);
}

static inline real3 intersect_dir_to_local_real(global const dev_prim *p, float3 d)
{
	real3 v = convert_real3(d);
	return (real3)(dot(convert_real3(p->a.xyz), v), dot(convert_real3(p->b.xyz), v), dot(convert_real3(p->c.xyz), v));
}

/* The component k (0, 1, 2) of v. */
static inline float intersect_axis(float3 v, int k)
{
	return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

/* A point in the space of a shape that has one (an ellipsoid's unit sphere, a
 * box's cube...) or of an instance (its mesh's): the rows a, b, c are the map
 * from world space. */
static inline float3 intersect_to_local(global const dev_prim *p, float3 x)
{
	return (float3)(dot(p->a.xyz, x) + p->a.w, dot(p->b.xyz, x) + p->b.w, dot(p->c.xyz, x) + p->c.w);
}

/* The same about a centre c, for a shape whose rows' w is the map's value at c
 * (lower_local_rows_about): only x - c is rounded, which keeps a shape far
 * from the origin as precise as one near it. */
static inline float3 intersect_to_local_about(global const dev_prim *p, float3 c, float3 x)
{
	float3 v = x - c;
	return (float3)(dot(p->a.xyz, v) + p->a.w, dot(p->b.xyz, v) + p->b.w, dot(p->c.xyz, v) + p->c.w);
}

/* A direction into that space: not unit length there, so t keeps its meaning. */
static inline float3 intersect_dir_to_local(global const dev_prim *p, float3 d)
{
	return (float3)(dot(p->a.xyz, d), dot(p->b.xyz, d), dot(p->c.xyz, d));
}

/* A normal in that space to world space: normals map by the transpose of the
 * world-to-local map. */
static inline float3 intersect_normal_to_world(global const dev_prim *p, float3 n)
{
	return normalize(n.x * p->a.xyz + n.y * p->b.xyz + n.z * p->c.xyz);
}

/* intersect_to_local_about undone: a point q of the shape's space to world
 * space, for the emitters that sample a point there. The rows a, b, c are M's;
 * M's inverse has the columns b x c, c x a, a x b over det M. */
static inline float3 intersect_to_world_about(global const dev_prim *p, float3 c, float3 q)
{
	float3 a = p->a.xyz, b = p->b.xyz, cc = p->c.xyz, v = q - (float3)(p->a.w, p->b.w, p->c.w);
	float3 bc = cross(b, cc), ca = cross(cc, a), ab = cross(a, b);
	return c + (v.x * bc + v.y * ca + v.z * ab) / dot(a, bc);
}

/* How much world space's area element is the shape's space's, on a surface
 * whose unit normal there is n: |M^T n| / |det M| (Nanson's formula), constant
 * over a flat face however the shape is scaled or sheared. The area densities
 * of emitters sampled in their own space are divided by it. */
static inline float intersect_area_scale(global const dev_prim *p, float3 n)
{
	float3 a = p->a.xyz, b = p->b.xyz, c = p->c.xyz;
	return length(n.x * a + n.y * b + n.z * c) / fabs(dot(a, cross(b, c)));
}

/* An area density at the point t along the unit direction wi, on a surface of
 * unit normal n, as a density in the solid angle seen from the ray's origin;
 * 0 edge-on. */
static inline float intersect_area_to_solid_angle(float pdf_area, float3 n, float3 wi, float t)
{
	float cos_l = fabs(dot(n, wi));
	return cos_l > 0.0f ? pdf_area * t * t / cos_l : 0.0f;
}

/* An orthonormal basis around n without branches on a special axis
 * (the materials' lobes, and a sphere's cone of directions toward it)
 * (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017). */
static inline void intersect_basis(float3 n, float3 *t, float3 *b)
{
	float s = n.z >= 0.0f ? 1.0f : -1.0f;
	float a = -1.0f / (s + n.z);
	float c = n.x * n.y * a;
	*t = (float3)(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
	*b = (float3)(c, s + n.y * n.y * a, -n.y);
}

/* A shape's own numbers: the a of its PRIM_DATA record. */
static inline float4 intersect_data(global const dev_prim *prims, global const dev_prim *p)
{
	return prims[p->link].a;
}

/* The nearer of two roots lo <= hi that lies in (tmin, tmax), else tmax. */
static inline float intersect_pick(float lo, float hi, float tmin, float tmax)
{
	if (lo > tmin && lo < tmax)
		return lo;
	if (hi > tmin && hi < tmax)
		return hi;
	return tmax;
}
