/* shape_box.cl: POV-Ray's box, kept as the map from world space to the cube
 * [-1, 1]^3, so a transformed box is still one primitive; the map is about the
 * box's centre, the a of its PRIM_DATA record (intersect_to_local_about). */

static inline float3 box_local(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return intersect_to_local_about(p, intersect_data(prims, p).xyz, x);
}

/* The slabs of the cube: the entering face, or the leaving one from inside. A
 * direction component of 0 gives infinities of the same sign outside that slab
 * (a miss) and of opposite signs inside it. */
static inline float box_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                           float tmin, float tmax)
{
	float3 oo = box_local(prims, p, o), dd = intersect_dir_to_local(p, d);
	float3 inv = 1.0f / dd;
	float3 t0 = (-1.0f - oo) * inv, t1 = (1.0f - oo) * inv;
	float3 lo = fmin(t0, t1), hi = fmax(t0, t1);
	float enter = fmax(fmax(lo.x, lo.y), lo.z), leave = fmin(fmin(hi.x, hi.y), hi.z);
	if (!(enter <= leave))
		return tmax;
	return intersect_pick(enter, leave, tmin, tmax);
}

/* The face the point is nearest to, in the cube's space. */
static inline float3 box_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = box_local(prims, p, x), a = fabs(q);
	float3 n = a.x >= a.y && a.x >= a.z ? (float3)(sign(q.x), 0.0f, 0.0f)
	         : a.y >= a.z ? (float3)(0.0f, sign(q.y), 0.0f) : (float3)(0.0f, 0.0f, sign(q.z));
	return intersect_normal_to_world(p, n);
}

/* POV-Ray's uv: the six faces unfolded as a cross, a quarter of u and a third
 * of v each, none mirrored seen from outside; the point from the box's
 * corner at its least x, y, z, a fraction of each side. */
static inline float2 box_uv(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = box_local(prims, p, x), a = fabs(q), f = 0.5f * (q + 1.0f);
	if (a.x >= a.y && a.x >= a.z)
		return q.x < 0.0f ? (float2)(f.z / 4.0f, (1.0f + f.y) / 3.0f)
		                  : (float2)(0.75f - f.z / 4.0f, (1.0f + f.y) / 3.0f);
	if (a.y >= a.z)
		return q.y < 0.0f ? (float2)(0.25f + f.x / 4.0f, f.z / 3.0f)
		                  : (float2)(0.25f + f.x / 4.0f, 1.0f - f.z / 3.0f);
	return q.z < 0.0f ? (float2)(1.0f - f.x / 4.0f, (1.0f + f.y) / 3.0f)
	                  : (float2)(0.25f + f.x / 4.0f, (1.0f + f.y) / 3.0f);
}

static inline bool box_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 a = fabs(box_local(prims, p, x));
	return a.x < 1.0f && a.y < 1.0f && a.z < 1.0f;
}
