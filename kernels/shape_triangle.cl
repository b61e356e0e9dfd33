/* shape_triangle.cl: triangles and smooth triangles (whose shading normals
 * shape.cl interpolates from the normals buffer). A triangle has no inside. */

/* Watertight ray/triangle intersection (Woop, Benthin and Wald, JCGT 2013): the
 * corners are sheared into a space where the ray runs along +z, and the edge
 * functions are evaluated there from the corners themselves, so two triangles
 * that share an edge compute the same edge function for it with opposite signs:
 * a ray through the edge, or through a shared corner, hits one of them. */
/* The ray's part of that test, the same for every triangle, which a mesh's
 * traversal makes once a ray (traverse.cl): the order of the axes x, y, z of
 * the sheared space (one of six, triangle_order) and the shear. */
typedef struct {
	int perm;    /* the order: 2 kz, plus 1 where x and y are swapped (triangle_order) */
	float sx, sy, sz;
	int kx, ky, kz;   /* the same order as axis numbers (traverse.cl's blocks of four) */
} triangle_ray;

/* v's axes in a ray's order (triangle_setup's perm): six constant shuffles,
 * the same one taken for every triangle of a ray. OpenCL's shuffle with the
 * order as a variable mask went through memory on PoCL (a store and three
 * loads a corner, 8% of the mesh level's samples under perf); a switch of
 * constant shuffles is a jump the branch predictor learns and one vpermilps
 * a corner (issue 18). */
static inline float4 triangle_order(float4 v, int perm)
{
	switch (perm) {
	case 0: return v.yzxw;
	case 1: return v.zyxw;
	case 2: return v.zxyw;
	case 3: return v.xzyw;
	case 4: return v.xyzw;
	default: return v.yxzw;
	}
}

static inline triangle_ray triangle_setup(float3 d)
{
	float3 ad = fabs(d);
	int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
	int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
	float dz = intersect_axis(d, kz);
	if (dz < 0.0f) {   /* keep the winding: swap x and y */
		int k = kx; kx = ky; ky = k;
	}
	triangle_ray r = { 2 * kz + (dz < 0.0f), intersect_axis(d, kx) / dz, intersect_axis(d, ky) / dz,
	                   1.0f / dz, kx, ky, kz };
	return r;
}

/* The test with the ray's part made: each corner is moved to the ray's
 * origin and its axes put in the sheared space's order by one constant
 * shuffle (the same numbers as shuffling first: a difference of two floats
 * does not depend on their lane).
 * Always inlined: it has several callers (the traversal levels, CSG), and as a
 * call it spilled the traversal's registers at every leaf; inlined, make bench's
 * traversal-only rays run 3-7% faster (issue 18). */
static inline __attribute__((always_inline)) float triangle_intersect_ray(float3 o, const triangle_ray *r, global const dev_prim *p, float tmin,
                                    float tmax)
{
	float4 ro = (float4)(o, 0.0f);
	float4 a = triangle_order(p->a - ro, r->perm), b = triangle_order(p->b - ro, r->perm);
	float4 c = triangle_order(p->c - ro, r->perm);
	float sx = r->sx, sy = r->sy, sz = r->sz;
	float az = a.z, bz = b.z, cz = c.z;
	float ax = a.x - sx * az, ay = a.y - sy * az;
	float bx = b.x - sx * bz, by = b.y - sy * bz;
	float cx = c.x - sx * cz, cy = c.y - sy * cz;
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

static inline float triangle_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                                float tmin, float tmax)
{
	triangle_ray r = triangle_setup(d);
	return triangle_intersect_ray(o, &r, p, tmin, tmax);
}

static inline float3 triangle_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return normalize(cross(p->b.xyz - p->a.xyz, p->c.xyz - p->a.xyz));
}

static inline bool triangle_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return false;
}

static inline float smooth_triangle_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                                       float tmin, float tmax)
{
	return triangle_intersect(o, d, prims, p, tmin, tmax);
}

static inline float3 smooth_triangle_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return triangle_normal(prims, p, x);
}

static inline bool smooth_triangle_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return false;
}

/* x's barycentric weights in the triangle p: of b (x), of c (y). */
static inline float2 triangle_weights(global const dev_prim *p, float3 x)
{
	float3 e1 = p->b.xyz - p->a.xyz, e2 = p->c.xyz - p->a.xyz, w = x - p->a.xyz;
	float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
	float d20 = dot(w, e1), d21 = dot(w, e2), den = d00 * d11 - d01 * d01;
	return den != 0.0f ? (float2)((d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den) : (float2)(0.0f);
}

/* A mesh triangle's uv at x: its corners' uv (after its normals, when the
 * first normal's w says they are there) interpolated as POV-Ray's
 * Mesh::UVCoord does; a triangle without uv, <0, 0>, as POV-Ray's default. */
static inline float2 triangle_uv(global const dev_prim *p, global const float4 *n, float3 x)
{
	if (p->type != PRIM_SMOOTH_TRIANGLE || n[0].w != 1.0f)
		return (float2)(0.0f);
	float2 b = triangle_weights(p, x);
	return (1.0f - b.x - b.y) * n[3].xy + b.x * n[4].xy + b.y * n[5].xy;
}

/* Barycentric interpolation of a smooth triangle's three normals at x. */
static inline float3 triangle_smooth_normal(global const dev_prim *p, global const float4 *n, float3 x)
{
	float3 e1 = p->b.xyz - p->a.xyz, e2 = p->c.xyz - p->a.xyz, w = x - p->a.xyz;
	float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
	float d20 = dot(w, e1), d21 = dot(w, e2), den = d00 * d11 - d01 * d01;
	float v = den != 0.0f ? (d11 * d20 - d01 * d21) / den : 0.0f;
	float u = den != 0.0f ? (d00 * d21 - d01 * d20) / den : 0.0f;
	float3 s = (1.0f - u - v) * n[0].xyz + v * n[1].xyz + u * n[2].xyz;
	return dot(s, s) > 0.0f ? normalize(s) : (float3)(0.0f);
}

/* As an emitter (shape.cl's shape_emit_sample and shape_emit_pdf): a point
 * uniform over its area from u1, u2; the density of the point t along wi
 * from x in solid angle, pick times it, area the triangle's (the emitter
 * table's). */
static inline bool triangle_emit_sample(global const dev_prim *prims, global const dev_prim *p, float3 x, float u1,
                                        float u2, float3 *wi, float3 *pos)
{
	float su = sqrt(u1);
	*pos = (1.0f - su) * p->a.xyz + su * (1.0f - u2) * p->b.xyz + su * u2 * p->c.xyz;
	*wi = normalize(*pos - x);
	return true;
}

static inline float triangle_emit_pdf(global const dev_prim *prims, global const dev_prim *p, float3 x, float3 wi,
                                      float t, float pick, float area)
{
	float3 nl = normalize(cross(p->b.xyz - p->a.xyz, p->c.xyz - p->a.xyz));
	float cos_l = fabs(dot(nl, wi));
	return cos_l > 0.0f ? pick * t * t / (area * cos_l) : 0.0f;
}
