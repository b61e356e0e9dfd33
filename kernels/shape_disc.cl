/* shape_disc.cl: POV-Ray's disc (src/shape_disc.c), kept as the map from world
 * space to the unit disc in z = 0, its normal +z, about its centre; its
 * PRIM_DATA records: x the square of the hole's radius (over the disc's), then
 * the centre (xyz). Its inside is z < 0. */

static inline float3 disc_local(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return intersect_to_local_about(p, prims[p->link + 1].a.xyz, x);
}

/* The ray starts from its point nearest the centre, so the distance from the
 * centre keeps its precision when the disc is far away. */
static inline float disc_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                            float tmin, float tmax)
{
	float3 oo = disc_local(prims, p, o), dd = intersect_dir_to_local(p, d);
	if (dd.z == 0.0f)
		return tmax;
	float ts = -dot(oo, dd) / dot(dd, dd);
	oo += ts * dd;
	float s = -oo.z / dd.z, t = ts + s;
	if (!(t > tmin && t < tmax))
		return tmax;
	float2 w = oo.xy + s * dd.xy;
	float r2 = dot(w, w);
	return r2 >= intersect_data(prims, p).x && r2 <= 1.0f ? t : tmax;
}

static inline float3 disc_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return intersect_normal_to_world(p, (float3)(0.0f, 0.0f, 1.0f));
}

static inline bool disc_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return disc_local(prims, p, x).z < 0.0f;
}
